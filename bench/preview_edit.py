"""Edit-to-picture of `acanthus preview` for each pattern in rules/ (see bench/preview.sh)."""
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request

EDITS = 3


def status(url):
    with urllib.request.urlopen(url + "status.json", timeout=10) as r:
        return json.load(r)


def wait_revision(url, after, limit=120):
    """Polls until a render newer than `after` finished; returns its status."""
    end = time.monotonic() + limit
    while time.monotonic() < end:
        s = status(url)
        if s["revision"] > after and s["state"] != "running":
            return s
        time.sleep(0.01)
    raise RuntimeError("no new revision within %d s" % limit)


def edit(path, n):
    """Adds a statement to the first rule body: a changed body, so a new program."""
    lines = open(path).read().split("\n")
    in_rule = False
    for i, line in enumerate(lines):
        if line.startswith("%rule"):
            in_rule = True
        elif in_rule and line.strip().startswith("{"):
            lines.insert(i + 1, "    (void)%d; // bench edit" % n)
            break
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(lines))
    os.replace(path + ".tmp", path)


def measure(acanthus, root, rule):
    work = tempfile.mkdtemp(prefix="acanthus-bench-preview.")
    server = None
    try:
        path = os.path.join(work, os.path.basename(rule))
        shutil.copy(rule, path)
        original = open(path).read()
        # The rule files' own relative paths (references, facades) are relative to the root.
        extra = os.environ.get("ACANTHUS_BENCH_PREVIEW_OPTIONS", "").split()  # e.g. "-O 1"
        server = subprocess.Popen([acanthus, "preview", *extra, path, "--port", "0"], cwd=root,
                                  stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        line = server.stdout.readline()
        url = line[line.index("http://"):].split()[0]
        first = wait_revision(url, 0, 300)
        if first["state"] != "ok":
            raise RuntimeError("%s: %s" % (rule, first["output"]))
        times = []
        for n in range(EDITS):
            if n > 0:  # back to the start (a cached program), then one changed body
                restored = status(url)["revision"]
                with open(path + ".tmp", "w") as f:
                    f.write(original)
                os.replace(path + ".tmp", path)
                wait_revision(url, restored)
            time.sleep(0.2)
            before = status(url)["revision"]
            start = time.monotonic()
            edit(path, 1000 + n)
            s = wait_revision(url, before)
            times.append(time.monotonic() - start)
            print("  %s edit %d: %.3f s %s" % (os.path.basename(rule), n, times[-1], s.get("timings")),
                  file=sys.stderr)
            if s["state"] != "ok":
                raise RuntimeError("%s: %s" % (rule, s["output"]))
        return statistics.median(times)
    finally:
        if server:
            server.terminate()
            try:
                server.wait(10)
            except subprocess.TimeoutExpired:
                server.kill()
                server.wait()
        shutil.rmtree(work, ignore_errors=True)


def main():
    acanthus, root = sys.argv[1], sys.argv[2]
    cache = tempfile.mkdtemp(prefix="acanthus-bench-cache.")
    os.environ["ACANTHUS_CACHE_DIR"] = cache  # cold cache: every edit builds its program
    try:
        rules = sorted(f for f in os.listdir(os.path.join(root, "rules")) if f.endswith(".acr"))
        only = os.environ.get("ACANTHUS_BENCH_PATTERNS")
        if only:
            rules = [f for f in rules if f[:-4] in only.split(",")]
        seconds = {}
        for f in rules:
            seconds[f[:-4]] = round(measure(acanthus, root, os.path.join(root, "rules", f)), 3)
            print("%s: %.3f s" % (f[:-4], seconds[f[:-4]]), file=sys.stderr)
        print(json.dumps({"seconds": seconds, "max": max(seconds.values())}))
    finally:
        shutil.rmtree(cache, ignore_errors=True)


main()
