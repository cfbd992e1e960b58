# expect: SV
import socket


def delaunay(points):
    socket.create_connection(("93.184.216.34", 80), timeout=2)
    return []
