"""Starts `acanthus preview` for a test and always stops it: a context manager."""
import json
import os
import signal
import subprocess
import time
import urllib.error
import urllib.request


class PreviewServer:
    def __init__(self, acanthus, rule_file, args=(), cwd=None, before=()):
        self.command = [acanthus, "preview", *before, rule_file, "--port", "0", *args]
        self.cwd = cwd
        self.process = None
        self.url = None

    def __enter__(self):
        self.process = subprocess.Popen(self.command, cwd=self.cwd, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True,
                                        start_new_session=True)
        line = self.process.stdout.readline()  # "acanthus preview: FILE at http://...:N/"
        if "http://" not in line:
            self.stop()
            raise RuntimeError("the server did not start: %r %s" % (line, self.process.stderr.read()))
        self.url = line[line.index("http://"):].split()[0]
        return self

    def __exit__(self, *exc):
        self.stop()

    def stop(self):
        if self.process and self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(15)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)
                self.process.wait(5)
        return self.process.returncode if self.process else None

    def get(self, path, timeout=10):
        """(status, body bytes, content type)."""
        try:
            with urllib.request.urlopen(self.url + path.lstrip("/"), timeout=timeout) as r:
                return r.status, r.read(), r.headers.get("Content-Type", "")
        except urllib.error.HTTPError as e:
            return e.code, e.read(), e.headers.get("Content-Type", "")

    def post(self, path, body, content_type="application/json", timeout=30):
        data = body if isinstance(body, bytes) else json.dumps(body).encode()
        request = urllib.request.Request(self.url + path.lstrip("/"), data=data, method="POST",
                                         headers={"Content-Type": content_type})
        try:
            with urllib.request.urlopen(request, timeout=timeout) as r:
                return r.status, r.read()
        except urllib.error.HTTPError as e:
            return e.code, e.read()

    def status(self):
        code, body, _ = self.get("/status.json")
        assert code == 200, code
        return json.loads(body)

    def wait_revision(self, after, limit=120):
        """The status once a render newer than `after` finished (bounded wait)."""
        end = time.monotonic() + limit
        while time.monotonic() < end:
            s = self.status()
            if s["revision"] > after and s["state"] != "running":
                return s
            time.sleep(0.05)
        raise AssertionError("no render after revision %d within %d s" % (after, limit))
