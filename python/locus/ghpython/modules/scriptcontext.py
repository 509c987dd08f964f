"""``scriptcontext`` for GhPython scripts run by locus: ``sticky`` (a dictionary that lives as
long as the worker process, as GhPython's lives as long as Rhino) and ``doc`` (there is no Rhino
document: ``None``)."""

sticky = {}
doc = None
id = 1
