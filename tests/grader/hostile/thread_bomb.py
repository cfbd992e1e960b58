# expect: RE
import threading
import time


def delaunay(points):
    for _ in range(10000):
        threading.Thread(target=time.sleep, args=(100,), daemon=True).start()
    return []
