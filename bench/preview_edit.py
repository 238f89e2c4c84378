"""Edit-to-picture of `acanthus preview` for each pattern in rules/ (see bench/preview.sh): the
time from the save to the new revision on the server, and to the picture painted in headless
Chromium (tests/preview/paint_time.js)."""
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
# ACANTHUS_BENCH_TIMELINE=1: each save's steps, in ms after the file was written: the server's
# (/status.json "timeline") and the page's.
TIMELINE = bool(os.environ.get("ACANTHUS_BENCH_TIMELINE"))


def print_timeline(name, n, saved, status, steps, painted):
    """One save's steps, wall clock, in ms from the file's write."""
    rows = [(at, step) for step, at in status.get("timeline", [])]
    metrics = status.get("metrics", {}).get("seconds", {})
    ends = [at for at, step in rows if step == "program end"]
    if ends and "total" in metrics and "growth" in metrics and "render" in metrics:
        # The program's own clock: its growth's and its pictures' seconds, before its exit.
        rows.append((ends[0] - metrics["total"] + metrics["growth"], "(program) growth over"))
        rows.append((ends[0] - metrics["total"] + metrics["growth"] + metrics["render"],
                     "(program) pictures drawn"))
    for key in ("event", "fetch", "fetched", "loaded"):
        if key in steps:
            rows.append((steps[key], "(page) " + key))
    if painted:
        rows.append((painted, "(page) painted"))
    partials = 0
    print("  %s edit %d timeline:" % (name, n), file=sys.stderr)
    for at, step in sorted(rows):
        if step == "partial":
            partials += 1
            if partials > 3:
                continue
        print("    %7.1f ms  %s" % (1000 * (at - saved), step), file=sys.stderr)

def browser_command(root):
    """The paint timer's command without its URL, or None (and why) when it cannot run."""
    chromium = os.environ.get("ACANTHUS_CHROMIUM") or next(
        (shutil.which(c) for c in ("chromium", "chromium-browser", "google-chrome")
         if shutil.which(c)), None)
    if not chromium or not shutil.which("node"):
        return None, "no Chromium or no node"
    tests = os.path.join(root, "tests", "preview")
    if not os.path.isdir(os.path.join(tests, "node_modules", "puppeteer-core")):
        if subprocess.run(["npm", "ci", "--no-audit", "--no-fund"], cwd=tests,
                          stdout=sys.stderr).returncode != 0:
            return None, "npm ci failed in tests/preview"
    return ["node", os.path.join(tests, "paint_time.js"), chromium], None


class PaintTimer:
    """The page open in headless Chromium; painted(rev) is when it painted revision rev."""

    def __init__(self, command, url):
        self.process = subprocess.Popen(command[:2] + [url] + command[2:], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        if not line.startswith("ready "):
            raise RuntimeError("the browser did not show the first picture: %r" % line)

    def painted(self, revision, saved):
        """Seconds since the epoch when the page painted `revision` (or a later one), when it
        first painted anything after `saved` (the growth so far, or that picture), and the
        page's steps for the picture ({"event", "fetch", "fetched", "loaded"}, seconds)."""
        self.process.stdin.write("wait %d %d\n" % (revision, int(saved * 1000)))
        self.process.stdin.flush()
        words = self.process.stdout.readline().split(" ", 4)
        if len(words) < 4 or words[2] == "none":
            raise RuntimeError("the page did not paint revision %d" % revision)
        steps = json.loads(words[4]) if len(words) > 4 else {}
        return (int(words[2]) / 1000.0, int(words[3]) / 1000.0,
                {k: v / 1000.0 for k, v in steps.items() if isinstance(v, (int, float))})

    def close(self):
        self.process.stdin.close()
        try:
            self.process.wait(20)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


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


def measure(acanthus, root, rule, browser):
    """(server seconds, painted seconds, first-look seconds; None without a browser, processor
    seconds of the build and of the run): medians over the edits."""
    work = tempfile.mkdtemp(prefix="acanthus-bench-preview.")
    server = timer = None
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
        # The units of the first build, compiled after its picture (once per rule file, as a
        # person looks at the first picture): the edits below then compile only their own.
        # (they start 150 ms after the picture: seen compiling, then done)
        seen, start = False, time.monotonic()
        while time.monotonic() < start + 120:
            compiling = status(url).get("compiling_units")
            seen = seen or compiling
            if (seen and not compiling) or (not seen and time.monotonic() > start + 2):
                break
            time.sleep(0.02)
        if browser:
            timer = PaintTimer(browser, url)
        times, painted, looks, cpu = [], [], [], []
        for n in range(EDITS):
            if n > 0:  # back to the start (a cached program), then one changed body
                restored = status(url)["revision"]
                with open(path + ".tmp", "w") as f:
                    f.write(original)
                os.replace(path + ".tmp", path)
                back = wait_revision(url, restored)
                if timer:  # the page caught up too: no picture of it is taken for the edit's
                    timer.painted(back["revision"], time.time())
            time.sleep(0.2)
            before = status(url)["revision"]
            start, saved = time.monotonic(), time.time()
            edit(path, 1000 + n)
            s = wait_revision(url, before)
            times.append(time.monotonic() - start)
            if s["state"] != "ok":
                raise RuntimeError("%s: %s" % (rule, s["output"]))
            timings = s.get("timings", {})
            cpu.append((timings.get("build_cpu", 0.0), timings.get("grow_cpu", 0.0)))
            steps = {}
            if timer:
                at, first, steps = timer.painted(s["revision"], saved)
                painted.append(at - saved)
                looks.append(first - saved)
            if TIMELINE:
                print_timeline(os.path.basename(rule), n, saved, s, steps, painted[-1] + saved
                               if timer else None)
            print("  %s edit %d: server %.3f s, first look %s, painted %s %s" % (
                os.path.basename(rule), n, times[-1], "%.3f s" % looks[-1] if looks else "-",
                "%.3f s" % painted[-1] if painted else "-", s.get("timings")), file=sys.stderr)
        return (statistics.median(times), statistics.median(painted) if painted else None,
                statistics.median(looks) if looks else None,
                statistics.median(c[0] for c in cpu), statistics.median(c[1] for c in cpu))
    finally:
        if timer:
            timer.close()
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
        browser, why = browser_command(root)
        if not browser:
            print("bench preview: %s: server times only" % why, file=sys.stderr)
        seconds, painted, looks, build_cpu, grow_cpu = {}, {}, {}, {}, {}
        for f in rules:
            server_seconds, painted_seconds, look_seconds, build_s, grow_s = measure(
                acanthus, root, os.path.join(root, "rules", f), browser)
            name = f[:-4]
            seconds[name] = round(server_seconds, 3)
            build_cpu[name], grow_cpu[name] = round(build_s, 3), round(grow_s, 3)
            if painted_seconds is not None:
                painted[name] = round(painted_seconds, 3)
                looks[name] = round(look_seconds, 3)
            print("%s: server %.3f s, first look %s, painted %s" % (
                name, seconds[name], "%.3f s" % looks[name] if name in looks else "-",
                "%.3f s" % painted[name] if name in painted else "-"), file=sys.stderr)
        # Processor time of the build's commands and of the program's run (load-independent).
        result = {"seconds": seconds, "max": max(seconds.values()),
                  "build_cpu_seconds": build_cpu, "grow_cpu_seconds": grow_cpu}
        if painted:
            result.update({"painted_seconds": painted, "painted_max": max(painted.values()),
                           "first_look_seconds": looks, "first_look_max": max(looks.values())})
        print(json.dumps(result))
    finally:
        shutil.rmtree(cache, ignore_errors=True)


if __name__ == "__main__":
    main()
