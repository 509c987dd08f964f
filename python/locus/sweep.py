"""Design-space sweeps: many variants of one graph, on a local process pool or a Dask cluster.

A sweep evaluates one graph once per *variant* (one value for each swept input) and returns a
pandas DataFrame with one row per variant, in input order: the variant's input values, the
chosen outputs and the messages of the evaluation. A variant that fails (a value the input does
not take, a node that raises) is a row with its ``error``; the rest of the sweep goes on.

Work is shipped in batches of variants. Each worker process compiles the graph once, from its
text: the local pool gets the text when its processes start, a Dask cluster gets it once per
worker (``Client.scatter(..., broadcast=True)``), and batches then carry only the variants. Every
batch runs the same function on both backends, so their results are identical.
"""

from __future__ import annotations

import hashlib
import itertools
import math
import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Any, Iterable, Mapping, Sequence

from ._locus import Graph

__all__ = ["sweep", "variants"]

#: Columns every sweep row has besides its inputs and outputs.
MESSAGES = "messages"
ERROR = "error"

_SCALARS = (bool, int, float, str)


def _values_of(name: str, values: Any) -> list:
    """The list of values swept for one input."""
    try:
        import numpy as np
    except ImportError:  # pragma: no cover - numpy is a dependency
        np = None
    if np is not None and isinstance(values, np.ndarray):
        if values.ndim == 0:
            return [values.item()]
        if values.ndim == 1:
            return values.tolist()
        if values.ndim == 2 and values.shape[1] == 3:
            return [tuple(row) for row in values.tolist()]
        return list(values)
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        return [values]
    if isinstance(values, Mapping):
        raise TypeError(
            f"input {name!r}: sweep values are a list (or array) of values, one per variant; "
            "to sweep over trees give a list of dicts"
        )
    return list(values)


def variants(values: Mapping[str, Any], mode: str = "product") -> list[dict[str, Any]]:
    """The variants of a sweep, in order, as dicts from input name to value.

    ``mode="product"``: every combination, the last input varying fastest (as nested loops in
    the dict's order). ``mode="zip"``: the i-th value of every input together; all inputs must
    have as many values.
    """
    names = list(values)
    columns = [_values_of(n, values[n]) for n in names]
    if mode == "product":
        combos: Iterable[tuple] = itertools.product(*columns)
    elif mode == "zip":
        lengths = {n: len(c) for n, c in zip(names, columns)}
        if len(set(lengths.values())) > 1:
            raise ValueError(f"mode='zip' needs as many values for every input, found {lengths}")
        combos = zip(*columns)
    else:
        raise ValueError(f"mode is 'product' or 'zip', found {mode!r}")
    return [dict(zip(names, combo)) for combo in combos]


class _Spec:
    """What a worker needs to rebuild the graph: its text and the inputs the host had set."""

    __slots__ = ("text", "inputs", "key")

    def __init__(self, text: str, inputs: list):
        self.text = text
        self.inputs = inputs
        self.key = hashlib.sha256(text.encode()).hexdigest() + f"-{len(inputs)}-{id(self):x}"

    def __getstate__(self):
        return (self.text, self.inputs, self.key)

    def __setstate__(self, state):
        self.text, self.inputs, self.key = state


def _spec_of(graph: Graph | str | os.PathLike) -> _Spec:
    if isinstance(graph, Graph):
        _, (text, _path, inputs, _threads) = graph.__reduce__()
        return _Spec(text, list(inputs))
    if isinstance(graph, str) and ("\n" in graph or graph.lstrip().startswith("(")):
        return _Spec(Graph.from_text(graph).text, [])
    return _Spec(Graph.load(graph).text, [])


# One compiled graph per worker process and spec.
_GRAPHS: dict[str, Graph] = {}


def _graph_for(spec: _Spec) -> Graph:
    g = _GRAPHS.get(spec.key)
    if g is None:
        g = Graph.from_text(spec.text)
        g.threads = 1  # the workers are the parallelism
        for name, value in spec.inputs:
            g.set(name, value)
        _GRAPHS.clear()
        _GRAPHS[spec.key] = g
    return g


def _present(value: Any, geometry: str) -> Any:
    if geometry == "object" or value is None or isinstance(value, _SCALARS):
        return value
    if isinstance(value, list):
        return [_present(v, geometry) for v in value]
    if isinstance(value, dict):
        return {k: _present(v, geometry) for k, v in value.items()}
    return repr(value)


def _run_batch(spec: _Spec, start: int, batch: Sequence[Mapping[str, Any]], outputs: Sequence[str], geometry: str):
    """Evaluates a batch of variants; returns ``(start, rows)``, one row per variant."""
    g = _graph_for(spec)
    rows = []
    for variant in batch:
        row: dict[str, Any] = {}
        try:
            for name, value in variant.items():
                g.set(name, value)
            g.evaluate()
            for name in outputs:
                row[name] = _present(g[name], geometry)
            row[MESSAGES] = [str(m) for m in g.messages]
            row[ERROR] = None
        except Exception as e:  # a failing variant is a row, never a lost sweep
            row = {name: None for name in outputs}
            row[MESSAGES] = []
            row[ERROR] = f"{type(e).__name__}: {e}"
        rows.append(row)
    return start, rows


def _init_worker(spec: _Spec) -> None:
    _graph_for(spec)


def _failed(batch: Sequence, outputs: Sequence[str], error: BaseException) -> list[dict]:
    text = f"{type(error).__name__}: {error}"
    return [{**{name: None for name in outputs}, MESSAGES: [], ERROR: text} for _ in batch]


def _batches(items: list, size: int) -> list[tuple[int, list]]:
    return [(i, items[i : i + size]) for i in range(0, len(items), size)]


def sweep(
    graph: Graph | str | os.PathLike,
    values: Mapping[str, Any],
    mode: str = "product",
    outputs: Sequence[str] | None = None,
    client: Any = None,
    *,
    workers: int | None = None,
    batch_size: int | None = None,
    geometry: str = "object",
    progress: bool = True,
):
    """Evaluates every variant of ``graph`` and returns a pandas DataFrame, one row per variant.

    - ``graph``: a :class:`Graph` (its text and the inputs set on it are shipped), a path, or
      graph text.
    - ``values``: for each input to sweep, its values (a list, a numpy array, ...); see
      :func:`variants` for ``mode``.
    - ``outputs``: the outputs to keep (default: all). A one-item output is a scalar column; a
      list or tree output a list or dict per row.
    - ``client``: ``None`` runs on a local pool of ``workers`` processes (default: one per
      core; ``workers=0`` runs in this process); a ``dask.distributed.Client`` runs on its
      cluster.
    - ``geometry``: ``"object"`` keeps geometry as locus objects, ``"summary"`` as their
      ``repr`` text.

    The columns are the swept inputs, the outputs, ``messages`` (the evaluation's messages as
    text) and ``error`` (``None``, or why the variant failed).
    """
    import pandas as pd

    if geometry not in ("object", "summary"):
        raise ValueError(f"geometry is 'object' or 'summary', found {geometry!r}")
    spec = _spec_of(graph)
    probe = Graph.from_text(spec.text)
    all_outputs = list(probe.outputs)
    outputs = list(all_outputs if outputs is None else outputs)
    unknown = [o for o in outputs if o not in all_outputs]
    if unknown:
        raise KeyError(f"unknown outputs {unknown} (the graph's outputs are: {', '.join(all_outputs)})")
    known_inputs = list(probe.inputs)
    unknown = [n for n in values if n not in known_inputs]
    if unknown:
        raise KeyError(f"unknown inputs {unknown} (the graph's inputs are: {', '.join(known_inputs)})")

    todo = variants(values, mode)
    n = len(todo)
    if client is None:
        count = (os.cpu_count() or 1) if workers is None else workers
    else:
        count = max(1, len(client.scheduler_info().get("workers", {})))
    if batch_size is None:
        batch_size = max(1, min(1000, math.ceil(n / (max(count, 1) * 8))))
    batches = _batches(todo, batch_size)
    rows: list[list[dict] | None] = [None] * len(batches)
    index_of = {start: k for k, (start, _) in enumerate(batches)}

    from tqdm.auto import tqdm

    bar = tqdm(total=n, unit="variant", disable=not progress, desc="locus sweep")
    try:
        if client is not None:
            _run_dask(client, spec, batches, outputs, geometry, rows, index_of, bar)
        elif count == 0:
            for k, (start, batch) in enumerate(batches):
                rows[k] = _run_batch(spec, start, batch, outputs, geometry)[1]
                bar.update(len(batch))
        else:
            _run_local(count, spec, batches, outputs, geometry, rows, index_of, bar)
    finally:
        bar.close()

    records = []
    input_names = list(values)
    renamed = {o: (o if o not in input_names else f"{o} (output)") for o in outputs}
    for (_, batch), batch_rows in zip(batches, rows):
        assert batch_rows is not None
        for variant, row in zip(batch, batch_rows):
            record = dict(variant)
            for o in outputs:
                record[renamed[o]] = row[o]
            record[MESSAGES] = row[MESSAGES]
            record[ERROR] = row[ERROR]
            records.append(record)
    columns = input_names + [renamed[o] for o in outputs] + [MESSAGES, ERROR]
    data = {}
    for c in columns:
        values = [r[c] for r in records]
        # Numbers make numeric columns (a failed variant's None becomes NaN); anything else
        # (text, geometry, lists, messages, errors) stays Python objects, None included.
        numeric = all(v is None or (isinstance(v, (int, float)) and not isinstance(v, bool)) for v in values)
        data[c] = pd.Series(values) if numeric and c not in (MESSAGES, ERROR) else pd.Series(values, dtype=object)
    return pd.DataFrame(data, columns=columns)


def _run_local(count, spec, batches, outputs, geometry, rows, index_of, bar):
    # Spawned (not forked) workers: a fork would inherit thread pools it cannot use.
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=count, mp_context=context, initializer=_init_worker, initargs=(spec,)) as pool:
        futures = {pool.submit(_run_batch, spec, start, batch, outputs, geometry): (start, batch) for start, batch in batches}
        for future in as_completed(futures):
            start, batch = futures[future]
            try:
                _, result = future.result()
            except Exception as e:  # a worker died: its batch is reported, the rest goes on
                result = _failed(batch, outputs, e)
            rows[index_of[start]] = result
            bar.update(len(batch))


def _run_dask(client, spec, batches, outputs, geometry, rows, index_of, bar):
    from dask.distributed import as_completed as dask_completed

    shared = client.scatter(spec, broadcast=True, hash=False)
    futures = {}
    for start, batch in batches:
        f = client.submit(_run_batch, shared, start, batch, outputs, geometry, pure=False, retries=1)
        futures[f] = (start, batch)
    try:
        for future in dask_completed(list(futures)):
            start, batch = futures[future]
            try:
                _, result = future.result()
            except Exception as e:  # a worker died twice on this batch
                result = _failed(batch, outputs, e)
            rows[index_of[start]] = result
            bar.update(len(batch))
    finally:
        client.cancel(list(futures) + [shared])
