#!/usr/bin/env python3
"""A stand-in for figment-serve --worker in the worker pool's unit tests
(tests/serve/workers/test_WorkerPool.cpp): it speaks the pool's frames on fd 3 (each a 4-byte
little-endian length and that many bytes; a request is two frames, its kind then its text;
an answer two, a JSON header then the body) and does what the request's text says:

  echo:TEXT   200, "KIND:TEXT" (the kind the frames carried)
  count       200, how many requests this process has answered, this one included
  wait:PATH   reads one 3-byte token from the FIFO at PATH (blocks until the test writes one), then 200
  refuse      400 with a JSON error
  hang        never answers
  die         exits at once, answering nothing
"""
import json
import os
import signal
import struct

FD = 3


def read_exactly(size):
    data = b""
    while len(data) < size:
        chunk = os.read(FD, size - len(data))
        if not chunk:
            raise EOFError
        data += chunk
    return data


def receive():
    (size,) = struct.unpack("<I", read_exactly(4))
    return read_exactly(size).decode()


def send(data):
    os.write(FD, struct.pack("<I", len(data)) + data)


def answer(kind, text, answered):
    if text.startswith("echo:"):
        return 200, f"{kind}:{text[5:]}"
    if text == "count":
        return 200, str(answered)
    if text.startswith("wait:"):
        fifo = os.open(text[5:], os.O_RDONLY)
        try:
            os.read(fifo, 3)  # one token ("go\n"): one request through
        finally:
            os.close(fifo)
        return 200, "released"
    if text == "refuse":
        return 400, json.dumps({"error": "refused"})
    if text == "hang":
        signal.pause()
    if text == "die":
        os._exit(1)
    return 500, json.dumps({"error": "unknown: " + text})


def main():
    answered = 0
    try:
        while True:
            kind, text = receive(), receive()
            answered += 1
            status, body = answer(kind, text, answered)
            send(json.dumps({"status": status, "drapeCache": "miss", "drape": ""}).encode())
            send(body.encode())
    except EOFError:
        pass


if __name__ == "__main__":
    main()
