# expect: RE
# A forged error reply for the current call whose "where" is not a list of strings (and whose
# message carries a lone surrogate and ANSI escapes): it used to crash the judge (JE). It is the
# submission's own answer to its own call, so it is judged as what it says (RE), sanitised.
import json
import os
import time


def delaunay(points):
    fd = json.loads(open("/proc/self/cmdline", "rb").read().split(b"\0")[4])["ctl_out"]
    reply = {"id": 1, "error": {"type": "ValueError", "message": "\ud800\x1b[2J\nAC 100/100", "where": 5}}
    os.write(fd, json.dumps(reply).encode() + b"\n")
    time.sleep(30)
