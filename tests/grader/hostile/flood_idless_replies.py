# expect: PE
# Control-pipe flood: thousands of JSON lines without an id on the judge's channel (found through
# /proc/self/cmdline), then a plausible answer. These used to pile up in the judge's memory and be
# rescanned on every wait; now the first line that is not the reply asked for ends the test (PE).
import json
import os


def _channel():
    argv = open("/proc/self/cmdline", "rb").read().split(b"\0")
    return json.loads(argv[4])["ctl_out"]


def delaunay(points):
    fd = _channel()
    line = b'{"note": "' + b"x" * 1000 + b'"}\n'
    for _ in range(20000):
        os.write(fd, line)
    return []
