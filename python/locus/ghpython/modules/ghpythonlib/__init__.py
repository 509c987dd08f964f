"""``ghpythonlib`` for GhPython scripts run by locus: ``treehelpers`` (nested lists to trees
and back)."""
