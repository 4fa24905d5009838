"""Starting and stopping figment-serve for the service's tests, and reading its PNGs.

The server is started on a free loopback port (--port 0: it prints the one it took) in a
temporary folder, with its drape cache there; stop() sends SIGTERM and waits for it.
"""
import http.client
import json
import os
import signal
import struct
import subprocess
import tempfile
import zlib


class Server:
    def __init__(self, executable, *arguments):
        self.folder = tempfile.TemporaryDirectory(prefix="figment-serve-test-")
        cache = os.path.join(self.folder.name, "cache")
        self.process = subprocess.Popen(
            [executable, "--port", "0", "--cache", cache, *arguments],
            stdout=subprocess.PIPE, cwd=self.folder.name, text=True)
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
        self.folder.cleanup()
        return status


def png_pixels(data):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    position, idat, header = 8, b"", None
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        chunk = data[position + 8:position + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        position += 12 + length
    width, height, depth, colour = header[:4]
    assert depth == 8 and colour in (2, 6), "only 8-bit RGB(A)"
    channels = 3 if colour == 2 else 4
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = previous[x], previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, channels)])
        previous = line
    return width, height, rows


def count_near(rows, colour, tolerance):
    """Pixels whose every channel lies within `tolerance` of the colour's, brightness aside:
    a lit surface of that colour keeps its channels' ratios, so compare the normalised hue."""
    def hue(rgb):
        total = sum(rgb) or 1
        return [c / total for c in rgb]
    target = hue(colour)
    return sum(1 for row in rows for p in row
               if sum(p) > 60 and all(abs(a - b) <= tolerance for a, b in zip(hue(p), target)))
