# expect: WA
# A raw libc socket() + connect() bypasses the audit hook (network.py is SV through it). The jail
# has its own network namespace with no interface (root and an ordinary user alike): the connect
# fails, the submission answers [] (WA). A connection would be a RuntimeError (RE).
import ctypes
import socket
import struct

libc = ctypes.CDLL(None)


def delaunay(points):
    fd = libc.socket(socket.AF_INET, socket.SOCK_STREAM, 0)
    if fd < 0:
        return []
    addr = struct.pack("=HH4s8x", socket.AF_INET, socket.htons(80), bytes([1, 1, 1, 1]))
    if libc.connect(fd, addr, len(addr)) == 0:
        raise RuntimeError("connected to 1.1.1.1:80")
    return []
