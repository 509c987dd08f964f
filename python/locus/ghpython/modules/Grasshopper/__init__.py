"""``Grasshopper`` for GhPython scripts run by locus: ``DataTree`` and ``Kernel.Data.GH_Path``
(trees in and out of scripts) and ``Kernel.GH_RuntimeMessageLevel`` (for
``ghenv.Component.AddRuntimeMessage``)."""

from . import Kernel
from .Kernel.Data import GH_Path


class DataTree:
    """``Grasshopper.DataTree[T]``: lists of items by path. ``DataTree[object]()`` and
    ``DataTree()`` are the same."""

    def __class_getitem__(cls, item):
        return cls

    def __init__(self, other=None):
        self._branches = {}
        if isinstance(other, DataTree):
            for path, items in other._branches.items():
                self._branches[path] = list(items)

    @classmethod
    def _from_dict(cls, branches):
        tree = cls()
        for key, items in branches.items():
            tree._branches[GH_Path(key)] = list(items)
        return tree

    def _to_dict(self):
        return {str(path): list(items) for path, items in sorted(self._branches.items())}

    def EnsurePath(self, *path):
        p = GH_Path(*path)
        return self._branches.setdefault(p, [])

    def Add(self, item, path=None):
        self.EnsurePath(path if path is not None else GH_Path(0)).append(item)

    def AddRange(self, items, path=None):
        self.EnsurePath(path if path is not None else GH_Path(0)).extend(items)

    def Insert(self, item, path, index):
        self.EnsurePath(path).insert(index, item)

    def Branch(self, *path):
        if len(path) == 1 and isinstance(path[0], int):
            return sorted(self._branches.items())[path[0]][1]
        return self._branches[GH_Path(*path)]

    def PathExists(self, *path):
        return GH_Path(*path) in self._branches

    def Path(self, index):
        return sorted(self._branches)[index]

    @property
    def Paths(self):
        return sorted(self._branches)

    @property
    def Branches(self):
        return [items for _, items in sorted(self._branches.items())]

    @property
    def BranchCount(self):
        return len(self._branches)

    @property
    def DataCount(self):
        return sum(len(items) for items in self._branches.values())

    def AllData(self):
        return [item for _, items in sorted(self._branches.items()) for item in items]

    def Clear(self):
        self._branches.clear()

    def Flatten(self, path=None):
        items = self.AllData()
        self._branches = {GH_Path(path) if path is not None else GH_Path(0): items}

    def __repr__(self):
        return f"DataTree({self._to_dict()!r})"


__all__ = ["DataTree", "GH_Path", "Kernel"]
