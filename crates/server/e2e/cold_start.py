"""Cold start of `locus serve`: from starting the process to the first solve's answer.

Usage: cold_start.py LOCUS GRAPH [RUNS]. Prints the median and worst of RUNS starts (default 5),
each on a free loopback port, and stops every server it started."""
import base64
import json
import statistics
import subprocess
import sys
import time
import urllib.request


def one(locus, algo):
    start = time.perf_counter()
    proc = subprocess.Popen([locus, "serve", "--bind", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        line = proc.stdout.readline()
        url = line.strip().removeprefix("listening on ")
        body = json.dumps({"algo": algo, "values": []}).encode()
        req = urllib.request.Request(url + "/grasshopper", data=body,
                                     headers={"Content-Type": "application/json"})
        with urllib.request.urlopen(req, timeout=30) as r:
            answer = json.load(r)
        elapsed = time.perf_counter() - start
        assert any(v["ParamName"] == "D" for v in answer["values"]), answer
        return elapsed
    finally:
        proc.terminate()
        proc.wait(timeout=10)


def main():
    locus, graph = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    with open(graph, encoding="utf-8") as f:
        algo = base64.b64encode(f.read().encode()).decode()
    times = sorted(one(locus, algo) * 1000 for _ in range(runs))
    print(f"cold start to first answer: median {statistics.median(times):.1f} ms, "
          f"worst {times[-1]:.1f} ms over {runs} starts")


if __name__ == "__main__":
    main()
