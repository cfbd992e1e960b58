# expect: PE
# Control-pipe flood: replies with wrong ids, slowly, so that each one used to restart the wait
# without the deadline being checked (8000 lines held one test for 331 s). A wrong id is now a
# protocol violation at once (PE).
import json
import os
import time


def delaunay(points):
    fd = json.loads(open("/proc/self/cmdline", "rb").read().split(b"\0")[4])["ctl_out"]
    for k in range(8000):
        os.write(fd, json.dumps({"id": 10 ** 6 + k, "ok": []}).encode() + b"\n")
        time.sleep(0.01)
    return []
