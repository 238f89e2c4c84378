"""`acanthus preview` without a browser: status.json, diagnostics of a broken file, the last
good picture kept, a parameter change, an endless loop, what is refused.
Usage: check_server.py ACANTHUS"""
import glob
import http.client
import os
import re
import shlex
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from preview_server import PreviewServer  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
failures = []


def check(condition, what):
    print(("ok: " if condition else "FAIL: ") + what)
    if not condition:
        failures.append(what)


def raw_get(url, path):
    """A request whose path is sent exactly as written (no client-side normalisation)."""
    host, port = url[len("http://"):].rstrip("/").split(":")
    c = http.client.HTTPConnection(host, int(port), timeout=10)
    c.request("GET", path)
    r = c.getresponse()
    r.read()
    c.close()
    return r.status


def get_encoded(url, path, encodings="br, gzip"):
    """(status, Content-Encoding, body, seconds) of a GET that accepts compressed answers."""
    host, port = url[len("http://"):].rstrip("/").split(":")
    c = http.client.HTTPConnection(host, int(port), timeout=10)
    start = time.monotonic()
    c.request("GET", path, headers={"Accept-Encoding": encodings})
    r = c.getresponse()
    body = r.read()
    seconds = time.monotonic() - start
    c.close()
    return r.status, r.getheader("Content-Encoding"), body, seconds


def headers_of(url, path):
    """The answer's headers, names in lower case."""
    host, port = url[len("http://"):].rstrip("/").split(":")
    c = http.client.HTTPConnection(host, int(port), timeout=10)
    c.request("GET", path)
    r = c.getresponse()
    r.read()
    c.close()
    return {k.lower(): v for k, v in r.getheaders()}


def request_with(url, method, path, headers, timeout=60):
    host, port = url[len("http://"):].rstrip("/").split(":")
    c = http.client.HTTPConnection(host, int(port), timeout=timeout)
    c.request(method, path, headers=headers)
    r = c.getresponse()
    r.read()
    c.close()
    return r.status, r.getheader("Retry-After")


def never_stalls(server):
    """20 open event streams and 20 clients sending half a request: /status.json still answers."""
    host, port = server.url[len("http://"):].rstrip("/").split(":")
    streams, slow = [], []
    try:
        for _ in range(20):
            sock = socket.create_connection((host, int(port)), timeout=10)
            sock.sendall(b"GET /events HTTP/1.1\r\nHost: %s:%s\r\n\r\n" % (host.encode(),
                                                                          port.encode()))
            streams.append(sock)
        for sock in streams:
            first = sock.recv(65536)
            if not (first.startswith(b"HTTP/1.1 200") and b"text/event-stream" in first):
                check(False, "an event stream answered: %r" % first[:80])
                break
        for _ in range(20):
            sock = socket.create_connection((host, int(port)), timeout=10)
            sock.sendall(b"GET /status.json HTTP/1.1\r\nHo")
            slow.append(sock)
        worst = 0.0
        end = time.monotonic() + 3
        while time.monotonic() < end:
            for sock in slow:  # a byte now and then: never quite a timeout
                sock.sendall(b"s")
            start = time.monotonic()
            code = server.get("/status.json", timeout=10)[0]
            worst = max(worst, time.monotonic() - start)
            if code != 200:
                check(False, "status.json answered (%d)" % code)
            time.sleep(0.2)
        check(worst < 0.5, "20 event streams and 20 slow clients open: /status.json answered "
              "within %.3f s at worst" % worst)
    finally:
        for sock in streams + slow:
            sock.close()


def save(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main():
    acanthus = os.path.abspath(sys.argv[1])
    work = tempfile.mkdtemp(prefix="acanthus-preview-test.")
    try:
        rules = os.path.join(work, "bubbles.acr")
        good = open(os.path.join(HERE, "fixtures", "bubbles.acr")).read()
        save(rules, good)
        # The editor: a script that writes down how it was called.
        recorder, opened = os.path.join(work, "editor.py"), os.path.join(work, "opened.txt")
        with open(recorder, "w") as f:
            f.write("import sys\nopen(%r, 'w').write(' '.join(sys.argv[1:]))\n" % opened)
        editor = "'%s' '%s' --goto {file}:{line}:{column}" % (sys.executable, recorder)
        with PreviewServer(acanthus, rules, ["--region", "rect:80,50", "--body-time-limit", "2",
                                             "--time-limit", "8", "--editor", editor],
                           cwd=work) as server:
            s = server.wait_revision(0)
            check(s["state"] == "ok" and s["elements"] > 10 and s["phase"] == "done",
                  "first render ok with elements")
            if shutil.which("clang++"):
                # The first build was the whole file; its units are compiled after the picture,
                # and the status says so while they are.
                seen, end = [], time.monotonic() + 60
                while time.monotonic() < end and not (True in seen and seen[-1] is False):
                    seen.append(server.status()["compiling_units"])
                    time.sleep(0.01)
                check(True in seen and seen[-1] is False,
                      "compiling_units while the first build's units are compiled, then not "
                      "(%d looks, %d true)" % (len(seen), seen.count(True)))
            check(s["params"][0] == {"name": "max_radius", "type": "double", "default": "3.0",
                                     "range": ["0.5", "10"]}, "params with the declared range")
            check([p["type"] for p in s["params"]] == ["double", "double", "bool"], "param types")
            t = s["timings"]
            # Processor times of the build's commands (0 for a cached program) and of the run.
            check(t.get("build_cpu", -1) >= 0 and 0 < t.get("grow_cpu", 0) < 8 and
                  t["grow_cpu"] <= t["grow"] * 2 + 0.05,
                  "timings carry the build's and the run's processor time: %s" % t)
            code, first_svg, ctype = server.get("/render.svg")
            check(code == 200 and ctype.startswith("image/svg+xml") and b"<svg" in first_svg,
                  "/render.svg serves the render")
            code, view, ctype = server.get("/view.png")
            check(code == 200 and ctype == "image/png" and view[:4] == b"\x89PNG" and
                  list(struct.unpack(">II", view[16:24])) == s["picture"]["png"] and
                  s["picture"]["width"] > 0,
                  "/view.png serves the render as the PNG the page shows (%s)" % s["picture"])
            # The growth so far is served only while a render grows.
            check(s["partial"] == 0 and server.get("/partial.png")[0] == 404,
                  "no partial picture once the render is done (partial %s)" % s["partial"])
            # --port 0 took a free port and printed it; a second preview on that port is refused.
            port = int(server.url.rstrip("/").rsplit(":", 1)[1])
            check(port > 0, "--port 0 printed the port it took (%d)" % port)
            start = time.monotonic()
            second = subprocess.run([acanthus, "preview", rules, "--port", str(port)], cwd=work,
                                    capture_output=True, text=True, timeout=30)
            check(second.returncode == 1 and "in use" in second.stderr and
                  time.monotonic() - start < 10,
                  "a second preview on port %d exits 1: %s" % (port, second.stderr.strip()))
            check(server.status()["revision"] == s["revision"], "the first one still answers")

            # Never compressed: Brotli took up to 9 s for a render (docs/preview.md#speed).
            for path, start in [("/render.svg", b"<"), ("/status.json", b"{"), ("/", b"<"),
                                ("/preview.js", b"/"), ("/nothing", b"not found")]:
                code, encoding, body, seconds = get_encoded(server.url, path)
                check(code in (200, 404) and encoding is None and body.startswith(start) and
                      seconds < 1, "%s with Accept-Encoding: br, gzip comes plain (%d, %s, %.3f s)"
                      % (path, code, encoding, seconds))
            # Safety headers on every answer, errors included.
            for path in ["/", "/preview.js", "/render.svg", "/status.json", "/nothing"]:
                h = headers_of(server.url, path)
                csp = h.get("content-security-policy", "")
                check("frame-ancestors 'none'" in csp and "script-src 'self'" in csp and
                      "default-src 'none'" in csp and h.get("x-content-type-options") ==
                      "nosniff" and h.get("x-frame-options") == "DENY",
                      "%s: CSP, nosniff and frame-ancestors headers (%s)" % (path, h))
            check(get_encoded(server.url, "/render.svg")[2] == first_svg,
                  "the same bytes as without Accept-Encoding")
            rules_fired = {r["rule"]: r["successes"] for r in s["metrics"]["rules"]}
            check(rules_fired.get("seed --> dot") == 1, "per-rule metrics")

            # The rule code is built as units that compile apart (docs/preview.md#speed): the
            # picture is the one `acanthus run` draws with the page's command, `dot_count` (the
            # %source's variable both rules count with and the draw reads) one across them.
            shown = os.path.join(work, "shown.svg")
            command = shlex.split(s["command"])
            check(command[0] == "acanthus" and command[-2] == "-o", "the command: %s" % command)
            subprocess.run([acanthus, *command[1:-2], "-o", shown], cwd=work, check=True,
                           capture_output=True, timeout=120)
            check(open(shown, "rb").read() == first_svg, "the preview's picture is the program's")
            # A save that edits one rule body compiles that rule's unit alone.
            cache = (os.environ.get("ACANTHUS_CACHE_DIR") or
                     os.path.expanduser(os.path.join("~", ".cache", "acanthus")))
            units = os.path.join(cache, "units")
            # The first build is the whole file; its units (two rules, the draws, the tables,
            # then the draws optimised) are compiled after its picture: until none is being
            # compiled (a temporary `.NAME.o.tmp-XXXXXX`) and no new one came for 2 s.
            listing = lambda: set(os.listdir(units)) if os.path.isdir(units) else set()
            objects = lambda: {f for f in listing() if not f.startswith(".")}
            seen, since, deadline = listing(), time.monotonic(), time.monotonic() + 60
            while ((time.monotonic() - since < 2 or len(seen) != len(objects()))
                   and time.monotonic() < deadline):
                time.sleep(0.1)
                if listing() != seen:
                    seen, since = listing(), time.monotonic()
            before = objects()
            save(rules, good.replace("    $$.sterile = 1;",
                                     "    $$.sterile = 1; (void)%d;" % (time.time_ns() % 10**9)))
            s = server.wait_revision(s["revision"])
            added = sorted(objects() - before)
            check(s["state"] == "ok" and len(added) == 1 and added[0].startswith("bubbles-"),
                  "an edited rule body compiles its own unit only: %s" % added)
            save(rules, good)
            s = server.wait_revision(s["revision"])

            # A broken file: the compiler's diagnostic at its line, the last good picture kept.
            broken = good.replace("    $$.sterile = 1;", "    $$.sterile = 1;\n    $7.radius = 2;")
            save(rules, broken)
            s = server.wait_revision(s["revision"])
            d = s["diagnostics"]
            check(s["state"] == "error" and len(d) == 1 and d[0]["file"].endswith("bubbles.acr")
                  and d[0]["line"] == 26 and d[0]["column"] == 5, "diagnostic at 26:5: %s" % d)
            check("$7" in d[0]["message"] and "26 |     $7.radius = 2;" in s["output"],
                  "message and source line as the compiler prints them")
            check(server.get("/render.svg")[1] == first_svg, "last good picture kept")
            check(d[0].get("source") == {"first": 24, "lines": [
                "    $$0.order = dot_count++;", "    $$.sterile = 1;", "    $7.radius = 2;",
                "    return SUCCESS;", "}"]},
                "the source around the error: %s" % d[0].get("source"))
            # file:line opens the editor there; only the rule file and its imports.
            code, body = server.post("/open", {"file": d[0]["file"], "line": 26, "column": 5})
            deadline = time.monotonic() + 10
            while not os.path.exists(opened) and time.monotonic() < deadline:
                time.sleep(0.05)
            check(code == 200 and os.path.exists(opened) and open(opened).read() ==
                  "--goto %s:26:5" % os.path.realpath(rules),
                  "POST /open runs --editor at the line and column: %s %s" % (
                      code, open(opened).read() if os.path.exists(opened) else "not run"))
            os.remove(opened)
            for name in ["/etc/passwd", os.path.join(work, "editor.py"), ""]:
                code, body = server.post("/open", {"file": name, "line": 1})
                check(code == 403, "POST /open refuses %r (%d)" % (name, code))
            check(server.post("/open", {"file": d[0]["file"], "line": -1})[0] == 400,
                  "POST /open refuses a bad line")
            time.sleep(0.3)
            check(not os.path.exists(opened), "the editor ran for none of them")

            # A C++ error in a body shows at the rule file's line.
            save(rules, good.replace("    double r = min( max_radius, $goal.radius );",
                                     "    double r = min( max_radius, $goal.radius ) oops;"))
            s = server.wait_revision(s["revision"])
            d = s["diagnostics"]
            check(s["state"] == "error" and d and d[0]["file"].endswith("bubbles.acr") and
                  d[0]["line"] == 34, "C++ error at the rule file's line 34: %s" % d)
            # At the rule file's column, under its own source line; nothing about the
            # generated file.
            check(d and d[0]["column"] == 47 and
                  "\n    double r = min( max_radius, $goal.radius ) oops;\n" + " " * 46 + "^\n"
                  in s["output"] and "acanthus-build." not in s["output"] and
                  "acanthus::body" not in s["output"],
                  "C++ error at column 47 under the rule's own line: %s" % s["output"])

            # A misspelt standard header: the precompiled prelude takes the rule file's own
            # standard includes, and one that does not exist is the build's error, not a stall.
            save(rules, good + "\n%source\n#include <algoritm>\n%endsource\n")
            s = server.wait_revision(s["revision"])
            check(s["state"] == "error" and "algoritm" in s["output"],
                  "a misspelt #include <algoritm> is an error: %s" % s["output"][:200])
            save(rules, good + "\n%source\n#include <algorithm>\n%endsource\n")
            s = server.wait_revision(s["revision"])
            check(s["state"] == "ok", "with #include <algorithm> it renders: %s" % s["output"][:300])
            # Acanthus's own headers go into the precompiled prelude too (an imported library's
            # headers were half of its build); a misspelt one is the build's error.
            save(rules, good + "\n%source\n#include <acanthus/environment.hpp>\n%endsource\n")
            s = server.wait_revision(s["revision"])
            cache = (os.environ.get("ACANTHUS_CACHE_DIR") or
                     os.path.expanduser(os.path.join("~", ".cache", "acanthus")))
            preludes = [open(p).read() for p in glob.glob(os.path.join(cache, "prelude-*",
                                                                       "prelude.hpp"))]
            check(s["state"] == "ok" and any("#include <acanthus/environment.hpp>\n" in p
                                             for p in preludes),
                  "an #include <acanthus/...> is precompiled with the prelude: %s" % s["output"][:300])
            # The standard library's members generated code uses most are instantiated in the
            # prelude, and it precompiled (a prelude that fails falls back to slower builds).
            with_env = [p for p in glob.glob(os.path.join(cache, "prelude-*", "prelude.hpp"))
                        if "#include <acanthus/environment.hpp>\n" in open(p).read()]
            check(any("acanthus::prelude_detail" in open(p).read() and os.path.exists(p + ".gch")
                      for p in with_env),
                  "the prelude instantiates the common templates and is precompiled: %s" % with_env)
            save(rules, good + "\n%source\n#include <acanthus/no_such_header.hpp>\n%endsource\n")
            s = server.wait_revision(s["revision"])
            check(s["state"] == "error" and "no_such_header" in s["output"],
                  "a misspelt #include <acanthus/...> is an error: %s" % s["output"][:200])

            # Fixed again, then a parameter moved: a new picture without recompiling.
            save(rules, good)
            s = server.wait_revision(s["revision"])
            check(s["state"] == "ok", "fixed file renders again")
            code, _ = server.post("/settings", {"params": {"max_radius": "1.5"}})
            s = server.wait_revision(s["revision"])
            check(code == 200 and s["state"] == "ok" and "--param max_radius=1.5" in s["command"],
                  "parameter change re-renders: %s" % s["command"])
            check(server.get("/render.svg")[1] != first_svg, "the picture changed")
            code, _ = server.post("/settings", {"params": {"max_radius": "50"}})
            s = server.wait_revision(s["revision"])
            check(s["state"] == "error" and "outside the declared range [0.5, 10]" in s["output"],
                  "a value outside the range is refused by the program")
            server.post("/settings", {"params": {"max_radius": "3.0"}})
            s = server.wait_revision(s["revision"])

            # Downloads: the same render made again as PDF and PNG.
            code, body, ctype = server.get("/render.pdf", timeout=60)
            check(code == 200 and body.startswith(b"%PDF"), "/render.pdf is a PDF")
            code, body, ctype = server.get("/render.png", timeout=60)
            check(code == 200 and body.startswith(b"\x89PNG"), "/render.png is a PNG")

            # Programs run for requests: only for the page itself, a few at a time.
            page = "http://" + server.url[len("http://"):].rstrip("/")
            for path in ["/render.png", "/render.pdf", "/debug-frame.png?iteration=3"]:
                for headers in [{"Origin": "http://evil.example"},
                                {"Sec-Fetch-Site": "cross-site"}, {"Sec-Fetch-Site": "same-site"}]:
                    code = request_with(server.url, "GET", path, headers)[0]
                    check(code == 403, "GET %s with %s refused (%d)" % (path, headers, code))
            code = request_with(server.url, "GET", "/render.png",
                                {"Origin": page, "Sec-Fetch-Site": "same-origin"})[0]
            check(code == 200, "GET /render.png from the page itself (%d)" % code)
            answers = []
            threads = [threading.Thread(target=lambda: answers.append(
                request_with(server.url, "GET", "/render.png", {}))) for _ in range(12)]
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            check(all(a == (200, None) or a == (503, "2") for a in answers) and
                  any(a[0] == 200 for a in answers),
                  "12 PNG downloads at once: made (200) or refused as busy (503): %s" %
                  sorted(a[0] for a in answers))
            never_stalls(server)

            # rng seed, panel and seeds from the page; two quick changes: the later one wins
            # (the render in progress is cancelled).
            server.post("/settings", {"rng_seed": "7", "panel": "heart.svg"})
            server.post("/settings", {"seeds": [[100, 80]]})
            s = server.wait_revision(s["revision"])
            while "--seed" not in s["command"]:
                s = server.wait_revision(s["revision"])
            check(s["state"] == "ok" and "--rng-seed 7" in s["command"] and "heart.svg" in
                  s["command"] and "--seed 100,80" in s["command"], "rng seed, panel, seed: %s" %
                  s["command"])
            check(s["settings"]["panel"] == "heart.svg" and s["settings"]["seeds"] == ["100,80"],
                  "settings in status.json")
            code, _ = server.post("/panel", open(os.path.join(HERE, "..", "..", "examples",
                                                              "panels", "star.svg"), "rb").read(),
                                  "image/svg+xml")
            s = server.wait_revision(s["revision"])
            check(code == 200 and s["state"] == "ok" and s["settings"]["panel"] == "uploaded",
                  "an uploaded panel is used")
            # Uploads do not pile up: four more, and only the latest two are kept.
            star = open(os.path.join(HERE, "..", "..", "examples", "panels", "star.svg"),
                        "rb").read()
            for _ in range(4):
                server.post("/panel", star, "image/svg+xml")
            s = server.wait_revision(s["revision"])
            uploaded = re.search(r"(\S*)/uploaded-\d+\.svg", s["command"])
            kept = sorted(f for f in os.listdir(uploaded.group(1)) if f.startswith("uploaded-")) \
                if uploaded else []
            check(kept == ["uploaded-4.svg", "uploaded-5.svg"],
                  "only the latest two uploaded panels kept: %s (%s)" % (kept, s["command"]))
            server.post("/settings", {"panel": "", "rng_seed": "1", "seeds": []})
            s = server.wait_revision(s["revision"])

            # An endless loop: an error with the limit named; the server answers meanwhile.
            save(rules, good.replace("    $$.sterile = 1;",
                                     "    $$.sterile = 1;\n    for (volatile int i = 0;; ) { (void)i; }"))
            answered = []

            def poll():
                end = time.monotonic() + 4
                while time.monotonic() < end:
                    answered.append(server.get("/status.json", timeout=2)[0])
                    time.sleep(0.2)
            t = threading.Thread(target=poll)
            t.start()
            s = server.wait_revision(s["revision"], limit=60)
            t.join()
            check(s["state"] == "error" and "still running after 2 s" in s["output"],
                  "endless loop is an error: %s" % s["output"].strip())
            check(answered and all(c == 200 for c in answered), "status answered during the loop")
            check(server.get("/render.svg")[0] == 200, "render still served after the loop")

            # std::abort() in a body: the rule and its line, no limit named.
            save(rules, good.replace("    $$0.order = dot_count++;",
                                     "    $$0.order = dot_count++;\n    if (dot_count > 3) std::abort();"))
            s = server.wait_revision(s["revision"], limit=60)
            check(s["state"] == "error" and "aborted" in s["output"] and "dot --> dot" in
                  s["output"] and "bubbles.acr:" in s["output"] and "time-limit" not in
                  s["output"], "an abort names the rule and its line: %s" % s["output"].strip())

            # A newer save cancels a render in progress: the looping program is killed, and
            # only the newer render counts as a revision.
            looping = s["revision"]
            save(rules, good.replace("    $$.sterile = 1;",
                                     "    $$.sterile = 1;\n    for (volatile int j = 0;; ) { (void)j; }"))
            end = time.monotonic() + 60
            while time.monotonic() < end:
                now = server.status()
                if now["state"] == "running" and now["phase"] == "growing":
                    break
                time.sleep(0.05)
            save(rules, good)
            s = server.wait_revision(looping)
            check(s["state"] == "ok" and s["revision"] == looping + 1,
                  "the stale render was cancelled (revision %d after %d)" % (s["revision"], looping))

            # Only the page, its assets and the renders.
            for path in ["/../etc/passwd", "/..%2f..%2fetc%2fpasswd", "/panels/../README.md",
                         "/panels/..%2F..%2Frules%2Fdots.acr", "/bubbles.acr", "/nothing",
                         "/frames/../../bubbles.acr", "/preview/index.html", "/index.html/.."]:
                code = raw_get(server.url, path)
                check(code in (400, 404), "%s refused (%d)" % (path, code))
            for path in ["/", "/preview.js", "/preview.css", "/panels.json", "/panels/heart.svg"]:
                check(server.get(path)[0] == 200, "%s served" % path)
            code, _ = server.post("/panel", b"<svg>" + b" " * (5 << 20), "image/svg+xml")
            check(code == 413, "oversized body refused (%d)" % code)
            code, _ = server.post("/settings", {"panel": "../../etc/passwd"})
            check(code == 400, "unknown panel refused (%d)" % code)
            host, port = server.url[len("http://"):].rstrip("/").split(":")
            c = http.client.HTTPConnection(host, int(port), timeout=10)
            c.request("POST", "/settings", body=b'{"rng_seed": "3"}',
                      headers={"Origin": "http://evil.example", "Content-Type": "text/plain"})
            r = c.getresponse()
            r.read()
            c.close()
            check(r.status == 403, "a POST from another origin refused (%d)" % r.status)
            for name, want in [("rebound.example:%s" % port, 403), ("localhost:%s" % port, 200),
                               ("127.0.0.1:%s" % port, 200), ("[::1]:%s" % port, 200)]:
                c = http.client.HTTPConnection(host, int(port), timeout=10)
                c.request("GET", "/status.json", headers={"Host": name})
                r = c.getresponse()
                r.read()
                c.close()
                check(r.status == want, "GET with Host %s: %d (%d)" % (name, want, r.status))
            # Parameters naming files: only in the rule file's folder, the examples or the
            # server's own; links resolved first.
            os.symlink("/etc", os.path.join(work, "etc_link"))
            for value in ["/etc/hostname", "../../../../../../etc/hostname",
                          os.path.join(work, "etc_link", "hostname")]:
                code, body = server.post("/settings", {"params": {"smallest": value}})
                check(code == 400 and "outside the rule file's folder" in body.decode(),
                      "a parameter naming %s refused (%d)" % (value, code))
            for value in [os.path.join(work, "bubbles.acr"),
                          os.path.join(HERE, "..", "..", "examples", "panels", "star.svg"), "0.5"]:
                code, _ = server.post("/settings", {"params": {"smallest": value}})
                check(code == 200, "a parameter naming %s accepted (%d)" % (value, code))
            server.post("/settings", {"params": {"smallest": None}})
            code, _ = server.post("/settings", b"{not json")
            check(code == 400, "malformed settings refused (%d)" % code)
            # No library with stroke tools imported: none offered, strokes refused.
            code, body = server.post("/guides", {"strokes": [
                {"kind": "flow", "width": 10, "points": [[1, 2], [30, 40]]}]})
            check(server.status()["stroke_tools"] == [] and code == 409 and
                  "no library with stroke tools" in body.decode(),
                  "no stroke tools without a library that declares them (%d)" % code)
            rc = server.stop()
            check(rc == 0, "Ctrl-C stops the server with status 0 (%s)" % rc)
        # Saving an imported file re-renders too.
        lib = os.path.join(work, "lib")
        os.mkdir(lib)
        save(os.path.join(lib, "extra.acr"), "%param double extra_one = 1.0;\n")
        save(rules, '%import "extra"\n' + good)
        with PreviewServer(acanthus, rules, ["--region", "rect:60,40"], cwd=work,
                           before=["-I", lib]) as server:
            s = server.wait_revision(0)
            check(s["state"] == "ok" and "extra_one" in [p["name"] for p in s["params"]],
                  "imported parameter listed")
            save(os.path.join(lib, "extra.acr"),
                 "%param double extra_one = 1.0;\n%param int extra_two = 2 in [0, 5];\n")
            s = server.wait_revision(s["revision"])
            check(s["state"] == "ok" and "extra_two" in [p["name"] for p in s["params"]],
                  "saving an imported file re-renders")
        # A library's stroke tools come with its import, as its registration declares them:
        # growth's guides for a rule file that imports growth.
        guided = os.path.join(work, "guided.acr")
        save(guided, '%import "growth"\n' + good)
        with PreviewServer(acanthus, guided, ["--region", "rect:60,40"], cwd=work) as server:
            s = server.wait_revision(0)
            tools = s["stroke_tools"]
            check(s["state"] == "ok" and len(tools) == 1 and tools[0]["library"] == "growth" and
                  tools[0]["file_param"] == "growth_guides" and
                  tools[0]["kinds"] == ["flow", "boundary", "spray"],
                  "growth's stroke tools offered when it is imported: %s" % tools)
            # The library's own instantiations (growth_prelude.hpp) precompiled with its header.
            cache = (os.environ.get("ACANTHUS_CACHE_DIR") or
                     os.path.expanduser(os.path.join("~", ".cache", "acanthus")))
            with_growth = [p for p in glob.glob(os.path.join(cache, "prelude-*", "prelude.hpp"))
                           if "#include <acanthus/stdlib/growth.hpp>\n" in open(p).read()]
            check(any("#include <acanthus/stdlib/growth_prelude.hpp>" in open(p).read() and
                      os.path.exists(p + ".gch") for p in with_growth),
                  "growth's prelude instantiations precompiled with its header: %s" % with_growth)
            code, _ = server.post("/guides", {"library": "cells", "strokes": []})
            check(code == 409, "strokes for a library the program does not use refused (%d)" % code)
            # Guides are written beside the rule file without following links: neither a
            # link named like the guides file nor one named like a temporary of it is followed.
            outside = os.path.join(work, "outside")
            os.mkdir(outside)
            for name in ["guided.guides.svg", "guided.guides.svg.partial"]:
                target = os.path.join(outside, name + ".target")
                save(target, "keep\n")
                os.symlink(target, os.path.join(work, name))
            code, body = server.post("/guides", {"strokes": [
                {"kind": "flow", "width": 10, "points": [[1, 2], [30, 40]]}]})
            guides = os.path.join(work, "guided.guides.svg")
            check(code == 200 and not os.path.islink(guides) and
                  "<polyline" in open(guides).read(), "the guides replace a link of their name")
            check(all(open(os.path.join(outside, f)).read() == "keep\n"
                      for f in os.listdir(outside)), "no file a link pointed to was written")
            check(sorted(f for f in os.listdir(work) if f.startswith("guided.guides")) ==
                  ["guided.guides.svg", "guided.guides.svg.partial"], "no temporary left")
            s = server.status()
            check(s["settings"]["params"].get("growth_guides") ==
                  os.path.join(work, "guided.guides.svg") and
                  s["settings"]["params"].get("growth_mode") == "flow",
                  "a flow stroke names the guides file and sets the mode parameter: %s" %
                  s["settings"]["params"])
            code, _ = server.post("/guides", {"strokes": [
                {"kind": "boundary", "points": [[1, 2], [30, 40]]}]})
            params = server.status()["settings"]["params"]
            check(code == 200 and "growth_mode" not in params and "growth_guides" in params,
                  "without a flow stroke the mode goes back to the rule file's: %s" % params)
        # A parameter of the same name, without the import: no tools.
        save(rules, '%param string growth_guides = "";\n' + good)
        with PreviewServer(acanthus, rules, ["--region", "rect:60,40"], cwd=work) as server:
            s = server.wait_revision(0)
            check(s["state"] == "ok" and s["stroke_tools"] == [],
                  "a rule file's own growth_guides parameter brings no stroke tools: %s %s" %
                  (s["state"], s["stroke_tools"]))
        # --memory-limit: a body that wants 1 GiB under a 256 MiB limit fails, and the
        # message names the limit; a bad limit is refused.
        save(rules, good.replace("    $$0.order = dot_count++;",
                                 "    $$0.order = dot_count++;\n    if (dot_count > 3) { "
                                 "std::vector<char> big(std::size_t(1) << 30); big[5] = 1; }"))
        with PreviewServer(acanthus, rules, ["--region", "rect:60,40", "--memory-limit", "256M"],
                           cwd=work) as server:
            s = server.wait_revision(0)
            check(s["state"] == "error" and "bad_alloc" in s["output"] and
                  "out of memory under --memory-limit 256 MiB" in s["output"],
                  "a run cut by --memory-limit says so: %s" % s["output"].strip())
        # A growth cut by --time-limit is a picture, but the status says which limit cut it.
        save(rules, good)
        with PreviewServer(acanthus, rules, ["--region", "rect:4000,4000", "--time-limit", "0.3"],
                           cwd=work) as server:
            s = server.wait_revision(0)
            check(s["state"] == "ok" and "cut by --time-limit 0.3 s" in s["phase"] and
                  "cut by --time-limit" in s["output"],
                  "a growth cut by the time limit says so: %s / %s" % (s["phase"], s["output"]))
        bad = subprocess.run([acanthus, "preview", rules, "--memory-limit", "5"], cwd=work,
                             capture_output=True, text=True, timeout=30)
        check(bad.returncode == 2 and "bad --memory-limit '5'" in bad.stderr,
              "--memory-limit 5 refused: %s" % bad.stderr.strip())
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)


main()
