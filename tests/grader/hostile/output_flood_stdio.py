# expect: OLE
import sys

data = sys.stdin.read()
while True:
    sys.stdout.write("0 1 2\n" * 10000)
