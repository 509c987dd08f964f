"""``System.Drawing.Color`` for GhPython scripts run by locus: a colour is locus's
``(r, g, b, a)`` tuple."""


class Color(tuple):
    def __new__(cls, r, g, b, a=255):
        return super().__new__(cls, (int(r), int(g), int(b), int(a)))

    R = property(lambda self: self[0])
    G = property(lambda self: self[1])
    B = property(lambda self: self[2])
    A = property(lambda self: self[3])

    @staticmethod
    def FromArgb(*args):
        if len(args) == 4:
            a, r, g, b = args
            return Color(r, g, b, a)
        r, g, b = args
        return Color(r, g, b)
