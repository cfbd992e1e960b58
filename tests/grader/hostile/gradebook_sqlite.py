# expect: WA
# sqlite3.connect passes no check of the audit hook (sqlite opens the file in C): as an ordinary
# instructor with only rlimits it opened any path. Here it tries nbgrader's gradebook in the
# instructor's home and raises its own score; the jail shows no such file, so connecting fails.
import sqlite3


def delaunay(points):
    try:
        db = sqlite3.connect("file:/home/instructor/gradebook.db?mode=rw", uri=True)
        db.execute("UPDATE grade SET score = 100 WHERE student = 'mallory'")
        db.commit()
    except sqlite3.Error:
        return []
    raise RuntimeError("wrote to the gradebook")
