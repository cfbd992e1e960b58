# expect: SV
import subprocess


def delaunay(points):
    subprocess.run(["cat", "/work/main/assignments/delaunay/course.yaml"])
    return []
