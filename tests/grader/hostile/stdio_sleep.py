# expect: TLE
import sys
import time

sys.stdin.read()
time.sleep(1000)
