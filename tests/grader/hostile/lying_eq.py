# expect: PE
class Liar(list):
    def __eq__(self, other):
        return True

    def __len__(self):
        return 3


def delaunay(points):
    return Liar()
