# expect: PE
import sys

sys.stdin.read()
print("three triangles, trust me")
