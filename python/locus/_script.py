"""Running a script node's script for each iteration of a request (inside a worker process).

Each call runs the script in a fresh namespace holding the inputs (and ``ghenv``), so that a
result never depends on which worker ran it or what ran before; ``scriptcontext.sticky`` is the
one dictionary that lives on between calls of one worker, as in GhPython (on a best-effort
basis: a worker may be replaced at any time). What the script prints (to standard output or
standard error) is collected per call. An exception ends the call with an error naming the
script line: ``line 3: ZeroDivisionError: division by zero``. A call that runs longer than the
time limit is interrupted (``signal.setitimer`` where the platform has it) by an exception that
``except Exception`` does not catch; the engine stops the whole process if the script still
does not return.
"""

import builtins
import io
import signal
import sys
import traceback

from . import _locus

SCRIPT_FILE = "<script>"

_compiled = {}


class ScriptTimeout(BaseException):
    """Raised in a script that runs past its time limit (not an ``Exception``, so that a
    script's ``except Exception`` does not swallow it)."""


def _on_alarm(signum, frame):
    raise ScriptTimeout()


def _compile(code):
    key = code
    if key not in _compiled:
        if len(_compiled) > 64:
            _compiled.clear()
        try:
            _compiled[key] = compile(code, SCRIPT_FILE, "exec")
        except SyntaxError as e:
            _compiled[key] = e
    return _compiled[key]


def _script_line(tb):
    """The line of the script where a traceback left it (the innermost frame in the script)."""
    line = None
    for frame, lineno in traceback.walk_tb(tb):
        if frame.f_code.co_filename == SCRIPT_FILE:
            line = lineno
    return line


def format_error(e, time_limit=None):
    """An exception as ``line N: Type: message`` (the last line of its traceback)."""
    if isinstance(e, ScriptTimeout):
        text = f"the script ran longer than its time limit of {time_limit:g} s"
        line = _script_line(e.__traceback__)
    elif isinstance(e, SyntaxError) and e.filename == SCRIPT_FILE:
        text = traceback.format_exception_only(type(e), e)[-1].strip()
        line = e.lineno
    else:
        text = traceback.format_exception_only(type(e), e)[-1].strip()
        line = _script_line(e.__traceback__)
    return f"line {line}: {text}" if line is not None else text


class _Component:
    """GhPython's ``ghenv.Component``: messages and the component's names."""

    def __init__(self, messages):
        self._messages = messages
        self.Name = "Python Script"
        self.NickName = "Python"
        self.Message = ""
        self.Description = ""

    def AddRuntimeMessage(self, level, text):
        name = str(getattr(level, "name", level)).lower()
        if name not in ("remark", "warning", "error"):
            name = "warning"
        self._messages.append((name, str(text)))


class _Env:
    """GhPython's ``ghenv``."""

    def __init__(self, messages):
        self.Component = _Component(messages)
        self.LocalScope = None


def _classify(value):
    """An output's value as the protocol's ``(kind, value)``: lists, tuples, sets and other
    iterables (not text, not geometry) are lists; dicts and ``DataTree``s are trees."""
    if value is None:
        return None
    to_tree = getattr(value, "_to_locus_tree", None)
    if to_tree is not None:
        return ("tree", to_tree())
    if isinstance(value, dict):
        return ("tree", value)
    if isinstance(value, (list, tuple, set, frozenset, range)) or (
        hasattr(value, "__iter__")
        and not isinstance(value, (str, bytes))
        and not hasattr(value, "_to_locus")
        and type(value).__module__.split(".")[0] not in ("locus",)
        and not hasattr(value, "__array__")
    ):
        return ("list", list(value))
    if hasattr(value, "__array__") and getattr(value, "ndim", 0) >= 1:
        return ("list", list(value))
    return ("item", value)


def _fresh(value):
    """A copy of a list or of a dict of lists (the items themselves are shared)."""
    if isinstance(value, dict):
        return {k: list(v) for k, v in value.items()}
    return list(value)


def run_request(request):
    """Runs the request's script once per iteration, yielding each iteration's reply."""
    code = _compile(request["code"])
    ghpython = request["ghpython"]
    time_limit = request["time_limit"]
    inputs = request["inputs"]
    outputs = request["outputs"]
    to_script = to_locus = None
    if ghpython:
        from . import ghpython as layer

        layer.install()
        to_script = layer.to_rhino
        to_locus = layer.to_locus
    shared = request["shared"]
    input_names = {name for name, _, _ in inputs}
    can_alarm = hasattr(signal, "setitimer")
    if can_alarm:
        signal.signal(signal.SIGALRM, _on_alarm)
    for iteration in request["iterations"]:
        messages = []
        printed = io.StringIO()
        error = None
        values = [None] * len(outputs)
        if isinstance(code, SyntaxError):
            error = format_error(code)
        else:
            namespace = {"__name__": "__main__", "__builtins__": builtins, "ghenv": _Env(messages)}
            for name in outputs:
                if name not in input_names:
                    namespace[name] = None
            for (name, access, hint), (is_shared, data) in zip(inputs, iteration):
                # Each call gets its own lists (the items are immutable locus values, or
                # Rhino objects made afresh), so that a script changing its inputs in place
                # does not change what a later call sees.
                value = _fresh(shared[data]) if is_shared else data
                if to_script is not None:
                    value = to_script(value, hint)
                namespace[name] = value
            saved = sys.stdout, sys.stderr
            sys.stdout = sys.stderr = printed
            try:
                if can_alarm:
                    signal.setitimer(signal.ITIMER_REAL, time_limit)
                try:
                    exec(code, namespace)
                finally:
                    if can_alarm:
                        signal.setitimer(signal.ITIMER_REAL, 0)
            except BaseException as e:  # noqa: BLE001 - every way a script ends is reported
                error = format_error(e, time_limit)
            finally:
                sys.stdout, sys.stderr = saved
            if error is None:
                values = [namespace.get(name) for name in outputs]
        converted = []
        for name, value in zip(outputs, values):
            try:
                if to_locus is not None:
                    value = to_locus(value)
                converted.append(_classify(value))
            except Exception as e:  # noqa: BLE001
                error = error or f"output {name}: {e}"
                converted.append(None)
        try:
            reply = _locus._script_done(outputs, converted, printed.getvalue(), messages, error)
        except Exception as e:  # an output with no locus form
            reply = _locus._script_done(
                outputs, [None] * len(outputs), printed.getvalue(), messages, error or str(e)
            )
        yield reply
