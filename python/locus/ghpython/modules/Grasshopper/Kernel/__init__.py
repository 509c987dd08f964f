"""``Grasshopper.Kernel``: ``Data.GH_Path`` and ``GH_RuntimeMessageLevel``."""

import enum

from . import Data


class GH_RuntimeMessageLevel(enum.Enum):
    Blank = 0
    Remark = 1
    Warning = 2
    Error = 3


__all__ = ["Data", "GH_RuntimeMessageLevel"]
