"""``ghpythonlib.treehelpers``: nested lists to ``DataTree``s and back, as in GhPython."""

from Grasshopper import DataTree
from Grasshopper.Kernel.Data import GH_Path


def list_to_tree(input, none_and_holes=True, source=None):
    """A tree whose branch ``{…;i}`` holds the i-th innermost list of a nested list."""
    source = [0] if source is None else list(source)
    tree = DataTree()

    def proc(items, path):
        if not isinstance(items, (list, tuple)):
            tree.Add(items, GH_Path(path))
            return
        if all(not isinstance(x, (list, tuple)) for x in items):
            branch = tree.EnsurePath(GH_Path(path))
            branch.extend(x for x in items if none_and_holes or x is not None)
            return
        for i, x in enumerate(items):
            proc(x, path + [i])

    proc(input, source)
    return tree


def tree_to_list(input, retrieve_base=lambda x: x[0]):
    """Nested lists from a tree: the inverse of ``list_to_tree`` (``retrieve_base`` picks the
    result from the outermost list, the first by default)."""
    all_lists = []
    for path in input.Paths:
        items = list(input.Branch(path))
        level = all_lists
        for i in path.Indices[:-1]:
            while len(level) <= i:
                level.append([])
            level = level[i]
        last = path.Indices[-1] if path.Indices else 0
        while len(level) <= last:
            level.append([])
        level[last] = items
    return retrieve_base(all_lists) if retrieve_base else all_lists
