"""``Grasshopper.Kernel.Data.GH_Path``: a tree path such as ``{0;1}``."""


class GH_Path:
    """A path of non-negative indices; ``GH_Path(0, 1)``, ``GH_Path([0, 1])`` or
    ``GH_Path("{0;1}")``."""

    __slots__ = ("Indices",)

    def __init__(self, *args):
        if len(args) == 1 and isinstance(args[0], GH_Path):
            indices = args[0].Indices
        elif len(args) == 1 and isinstance(args[0], str):
            text = args[0].strip().strip("{}")
            indices = tuple(int(i) for i in text.split(";")) if text else ()
        elif len(args) == 1 and isinstance(args[0], (list, tuple)):
            indices = tuple(int(i) for i in args[0])
        else:
            indices = tuple(int(i) for i in args)
        self.Indices = tuple(indices)

    @property
    def Length(self):
        return len(self.Indices)

    def __getitem__(self, i):
        return self.Indices[i]

    def AppendElement(self, index):
        return GH_Path(self.Indices + (int(index),))

    def PrependElement(self, index):
        return GH_Path((int(index),) + self.Indices)

    def CullElement(self):
        return GH_Path(self.Indices[:-1])

    def __eq__(self, other):
        return isinstance(other, GH_Path) and self.Indices == other.Indices

    def __lt__(self, other):
        return self.Indices < other.Indices

    def __hash__(self):
        return hash(self.Indices)

    def __str__(self):
        return "{" + ";".join(str(i) for i in self.Indices) + "}"

    ToString = __str__

    def __repr__(self):
        return f"GH_Path({str(self)!r})"
