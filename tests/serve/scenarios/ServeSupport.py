"""Starting and stopping figment-serve for the service's tests, and reading its PNGs.

The server is started on a free loopback port (--port 0: it prints the one it took) in a
temporary folder, with its drape cache there; stop() sends SIGTERM and waits for it.
RedisServer is a redis-server of the test's own, on a Unix socket in a temporary folder (no
TCP port at all), stopped at the end; JobWorker is figment-serve --job-worker on it.
ServerCase is a test case whose tests share one Server, started before the first and stopped
after the last.

A case that needs what a machine may lack (MakeHuman's data) is skipped only for that, decided
from the file system before any case runs (needs_makehuman), never from an answer; main()
then exits SKIP_RETURN_CODE, which ctest reports as skipped, not passed.
"""
import http.client
import socket
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "scripts"))
import pngrows  # noqa: E402 (scripts/pngrows.py, shared with scripts/size-pictures.py)


SKIP_RETURN_CODE = 77  # ctest's SKIP_RETURN_CODE of the service's Python tests


def makehuman_data():
    """The folder of MakeHuman's data figment-serve's workers read, as io/MakeHumanFiles.h's
    findMakeHumanData() looks for it ($FIGMENT_MAKEHUMAN_DIR; a "makehuman" folder of
    $FIGMENT_MODEL_PATH; the build's, which ctest passes as $FIGMENT_MAKEHUMAN_DEFAULT_DIR),
    or None where none holds 3dobjs/base.obj."""
    def holds(folder):
        return bool(folder) and os.path.isfile(os.path.join(folder, "3dobjs", "base.obj"))
    if os.environ.get("FIGMENT_MAKEHUMAN_DIR"):
        return os.environ["FIGMENT_MAKEHUMAN_DIR"] if holds(os.environ["FIGMENT_MAKEHUMAN_DIR"]) else None
    for folder in os.environ.get("FIGMENT_MODEL_PATH", "").split(os.pathsep):
        if folder and holds(os.path.join(folder, "makehuman")):
            return os.path.join(folder, "makehuman")
    default = os.environ.get("FIGMENT_MAKEHUMAN_DEFAULT_DIR")
    return default if holds(default) else None


needs_makehuman = unittest.skipUnless(
    makehuman_data(), "MakeHuman's data not found: scripts/setup.sh fetches it (or set FIGMENT_MAKEHUMAN_DIR)")


def main():
    """unittest.main(), but a run with a skipped case exits SKIP_RETURN_CODE (when none failed)."""
    result = unittest.main(exit=False).result
    if not result.wasSuccessful():
        sys.exit(1)
    if result.skipped:
        for case, why in result.skipped:
            print("skipped %s: %s" % (case.id(), why), file=sys.stderr)
        sys.exit(SKIP_RETURN_CODE)
    sys.exit(0)


def time_limited(arguments):
    """`arguments` with FIGMENT_SERVE_TIME_LIMIT's --time-limit where they set none: the
    sanitizer job (scripts/sanitize.sh) drapes some 30 times slower than Release, past the
    server's default 60 s a render, which would answer 504 for a render that is only slow.
    A case that sets its own limit (one that tests the 504) keeps it."""
    limit = os.environ.get("FIGMENT_SERVE_TIME_LIMIT")
    if not limit or "--time-limit" in arguments:
        return tuple(arguments)
    return (*arguments, "--time-limit", limit)


def claim_after(seconds):
    """A job worker's --claim-after: `seconds`, or under FIGMENT_SERVE_TIME_LIMIT that limit
    + 30 s, the server's own default. A worker takes over a job another has held that long,
    so the claim must outlast the longest a live worker may render one, or a job that is
    only slow is rendered twice: Release renders well within `seconds`, the sanitizer job's
    builds do not (a job was rendered twice there with 20 s)."""
    limit = os.environ.get("FIGMENT_SERVE_TIME_LIMIT")
    return str(max(float(seconds), float(limit) + 30) if limit else float(seconds))


class Server:
    def __init__(self, executable, *arguments, capture_log=False):
        """`capture_log`: its stderr goes to a file, read by log()."""
        self.folder = tempfile.TemporaryDirectory(prefix="figment-serve-test-")
        cache = os.path.join(self.folder.name, "cache")
        self.log_path = os.path.join(self.folder.name, "stderr")
        self.log_file = open(self.log_path, "w") if capture_log else None
        self.process = subprocess.Popen(
            [executable, "--port", "0", "--cache", cache, *time_limited(arguments)],
            stdout=subprocess.PIPE, stderr=self.log_file, cwd=self.folder.name, text=True)
        line = self.process.stdout.readline()
        if "http://" not in line:
            self.process.kill()
            raise RuntimeError("figment-serve did not start: " + repr(line))
        address = line.split("http://", 1)[1].split("/", 1)[0]
        self.host, port = address.rsplit(":", 1)
        self.port = int(port)
        self.url = "http://%s:%d/" % (self.host, self.port)

    def request(self, path, headers=None, method="GET"):
        """(status, headers as a dict with lower-case names, body bytes); the path is sent as is."""
        connection = http.client.HTTPConnection(self.host, self.port, timeout=600)
        try:
            connection.putrequest(method, path, skip_accept_encoding=True)
            for name, value in (headers or {}).items():
                connection.putheader(name, value)
            connection.endheaders()
            response = connection.getresponse()
            return response.status, {k.lower(): v for k, v in response.getheaders()}, response.read()
        finally:
            connection.close()

    def json(self, path):
        status, headers, body = self.request(path)
        return status, json.loads(body) if body else None

    def worker_pids(self):
        pids = []
        for task in os.listdir("/proc/%d/task" % self.process.pid):
            with open("/proc/%d/task/%s/children" % (self.process.pid, task)) as children:
                pids += [int(p) for p in children.read().split()]
        return pids

    def stop(self):
        """Stops the server; its exit status (0 when it stopped cleanly)."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
        status = self.process.wait(timeout=120)
        self.process.stdout.close()
        if self.log_file:
            self.log_file.close()
        self.folder.cleanup()
        return status

    def log(self):
        with open(self.log_path) as log:
            return log.read()


class ServerCase(unittest.TestCase):
    """One figment-serve for all the class's tests, with `server_arguments`; a server that does
    not exit cleanly (status 0) fails the class. The script sets `ServerCase.executable` from its
    command line before unittest.main()."""
    executable = None
    server_arguments = ("--workers", "1")

    @classmethod
    def setUpClass(cls):
        cls.server = Server(ServerCase.executable, *cls.server_arguments)

    @classmethod
    def tearDownClass(cls):
        status = cls.server.stop()
        if status != 0:
            raise AssertionError("figment-serve exited with %d" % status)


class RedisServer:
    """redis-server on a Unix socket in a temporary folder, no TCP port. Every write is
    appended to its log and synced before it is answered (appendfsync always), so a Redis
    killed and started again on the same folder has everything it acknowledged."""

    def __init__(self):
        self.folder = tempfile.TemporaryDirectory(prefix="figment-redis-test-")
        self.socket = os.path.join(self.folder.name, "redis.sock")
        self.url = self.socket
        self.process = None
        self.start()

    def start(self):
        self.process = subprocess.Popen(
            ["redis-server", "--port", "0", "--unixsocket", self.socket, "--unixsocketperm", "700",
             "--dir", self.folder.name, "--save", "", "--appendonly", "yes", "--appendfsync", "always",
             "--maxmemory", "256mb", "--maxmemory-policy", "volatile-lru",
             "--logfile", os.path.join(self.folder.name, "redis.log")],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        while True:  # until it answers, or has exited (ctest's TIMEOUT bounds the wait)
            try:
                if self.command("PING") == "PONG":
                    return
            except (OSError, RuntimeError):  # not listening yet, or still loading its log
                pass
            if self.process.poll() is not None:
                raise RuntimeError("redis-server did not start")
            time.sleep(0.05)

    def kill(self):
        """SIGKILL: a crash, nothing flushed beyond what each write synced."""
        self.process.kill()
        self.process.wait(timeout=60)

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            self.process.wait(timeout=60)
        self.folder.cleanup()

    def command(self, *arguments):
        """One command over a connection of its own; the reply as str, bytes (when not
        UTF-8), int, list or None. An error reply raises RuntimeError."""
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as connection:
            connection.settimeout(30)
            connection.connect(self.socket)
            message = b"*%d\r\n" % len(arguments)
            for argument in arguments:
                data = argument if isinstance(argument, bytes) else str(argument).encode()
                message += b"$%d\r\n%s\r\n" % (len(data), data)
            connection.sendall(message)
            with connection.makefile("rb") as reader:
                return _read_reply(reader)


def _read_reply(reader):
    line = reader.readline()
    if not line:
        raise OSError("redis closed the connection")
    kind, rest = line[:1], line[1:-2]
    if kind == b"+":
        return rest.decode()
    if kind == b"-":
        raise RuntimeError(rest.decode())
    if kind == b":":
        return int(rest)
    if kind == b"$":
        if int(rest) < 0:
            return None
        data = reader.read(int(rest) + 2)[:-2]
        try:
            return data.decode()
        except UnicodeDecodeError:
            return data
    if kind == b"*":
        return None if int(rest) < 0 else [_read_reply(reader) for _ in range(int(rest))]
    raise RuntimeError("unreadable reply %r" % line)


class JobWorker:
    """figment-serve --job-worker on `redis_url` with a drape cache of its own (a machine of
    its own); its stderr in `log` once stopped."""

    def __init__(self, executable, redis_url, name, *arguments):
        self.folder = tempfile.TemporaryDirectory(prefix="figment-jobs-test-")
        self.name = name
        self.log_file = open(os.path.join(self.folder.name, "stderr"), "w")
        self.process = subprocess.Popen(
            [executable, "--job-worker", "--redis", redis_url, "--consumer", name,
             "--cache", os.path.join(self.folder.name, "cache"), *arguments],
            stdout=subprocess.PIPE, stderr=self.log_file, cwd=self.folder.name, text=True)
        line = self.process.stdout.readline()
        if "job worker" not in line:
            self.process.kill()
            raise RuntimeError("figment-serve --job-worker did not start: " + repr(line))

    def log_so_far(self):
        """What it has written on stderr so far."""
        with open(self.log_file.name) as log:
            return log.read()

    def stop(self):
        """Stops it (SIGTERM, unless it was killed); its exit status."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
        status = self.process.wait(timeout=120)
        self.process.stdout.close()
        self.log_file.close()
        with open(self.log_file.name) as log:
            self.log = log.read()  # its stderr, kept
        self.folder.cleanup()
        return status


def png_pixels(data):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA PNG."""
    width, height, channels, lines = pngrows.unfiltered_rows(data)
    return width, height, [[tuple(line[i:i + 3]) for i in range(0, len(line), channels)] for line in lines]


def count_near(rows, colour, tolerance):
    """Pixels whose every channel lies within `tolerance` of the colour's, brightness aside:
    a lit surface of that colour keeps its channels' ratios, so compare the normalised hue."""
    def hue(rgb):
        total = sum(rgb) or 1
        return [c / total for c in rgb]
    target = hue(colour)
    return sum(1 for row in rows for p in row
               if sum(p) > 60 and all(abs(a - b) <= tolerance for a, b in zip(hue(p), target)))
