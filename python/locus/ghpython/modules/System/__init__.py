"""A sliver of .NET's ``System`` for GhPython scripts run by locus: ``System.Drawing.Color``
and ``System.Math``."""

import math as _math

from . import Drawing


class Math:
    PI = _math.pi
    E = _math.e
    Sqrt = staticmethod(_math.sqrt)
    Sin = staticmethod(_math.sin)
    Cos = staticmethod(_math.cos)
    Tan = staticmethod(_math.tan)
    Atan2 = staticmethod(_math.atan2)
    Abs = staticmethod(abs)
    Floor = staticmethod(_math.floor)
    Ceiling = staticmethod(_math.ceil)
    Pow = staticmethod(_math.pow)
    Min = staticmethod(min)
    Max = staticmethod(max)
    Round = staticmethod(round)


__all__ = ["Drawing", "Math"]
