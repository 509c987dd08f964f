"""The worker process of locus's Python script nodes (``locus._script_worker.main``).

The engine (the ``locus`` command, a host, or this package's own ``Graph``) starts one worker
per concurrently evaluated script node and keeps it for later evaluations. The worker reads
requests on its standard input and answers on its standard output, in the frames of
``locus_nodes::script::protocol`` (4-byte little-endian length, then the message, read and
written by the compiled ``locus._locus``, which shares that code with the engine):

1. it says hello (protocol version, package version, Python version);
2. for each request (a script and the data of every iteration of one node evaluation) it runs
   the script once per iteration (``locus._script.run_request``) and answers each iteration as
   it finishes;
3. it ends when its input closes.

Before anything else it takes the protocol's pipes for itself and points file descriptors 0
and 1 at ``/dev/null`` and standard error, so that nothing a script does (``input()``, a C
library writing to standard output) can touch the protocol.
"""

import os
import platform
import struct
import sys


def _read_exactly(stream, n):
    chunks = []
    while n > 0:
        chunk = stream.read(n)
        if not chunk:
            return None
        chunks.append(chunk)
        n -= len(chunk)
    return b"".join(chunks)


def read_frame(stream):
    """One frame's bytes, or ``None`` at the end of the stream."""
    header = _read_exactly(stream, 4)
    if header is None:
        return None
    (n,) = struct.unpack("<I", header)
    body = _read_exactly(stream, n)
    if body is None:
        raise EOFError("the stream ended inside a frame")
    return body


def write_frame(stream, data):
    stream.write(struct.pack("<I", len(data)))
    stream.write(data)
    stream.flush()


def _take_pipes():
    """The protocol's input and output, after moving fds 0 and 1 out of scripts' reach."""
    proto_in = os.fdopen(os.dup(0), "rb", buffering=0)
    proto_out = os.fdopen(os.dup(1), "wb", buffering=0)
    devnull = os.open(os.devnull, os.O_RDONLY)
    os.dup2(devnull, 0)
    os.close(devnull)
    os.dup2(2, 1)
    sys.stdin = open(os.devnull)
    sys.stdout = sys.stderr
    return proto_in, proto_out


def main():
    proto_in, proto_out = _take_pipes()
    from . import __version__, _locus, _script

    # The engine starts the worker with the working folder off the module path (so that the
    # package's sources cannot shadow the installed package); scripts may import from it.
    if os.getcwd() not in sys.path:
        sys.path.append(os.getcwd())

    write_frame(proto_out, _locus._script_hello(__version__, platform.python_version()))
    while True:
        frame = read_frame(proto_in)
        if frame is None:
            return 0
        try:
            request = _locus._script_read_request(frame)
        except Exception as e:  # a request that does not read: say so, keep serving
            write_frame(proto_out, _locus._script_fatal(f"the request does not read: {e}"))
            continue
        for reply in _script.run_request(request):
            write_frame(proto_out, reply)


if __name__ == "__main__":
    sys.exit(main())
