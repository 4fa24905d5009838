"""The guard's call from a pivy program (Python, Coin through pivy), through ctypes: the crash
scene of issue 28 is refused in one line and the caller's group is left as it was; a good scene
is added to it, and its shapes are checked before drawing.

    python3 tests/guard/test_GuardC.py build/guard/libfigment_guard.so

FIGMENT's nodes are found by name through Coin's dynamic loading: LD_LIBRARY_PATH must hold the
node kit's folder (tests/CMakeLists.txt sets it), and Coin must be loaded with its symbols global
(Coin finds how names are mangled by looking its own symbols up in the program, which Python's
default RTLD_LOCAL hides: without it every FIGMENT node reads as an unknown node). Exit status 0
when every check holds.
"""

import ctypes
import os
import sys
import tempfile

sys.setdlopenflags(sys.getdlopenflags() | os.RTLD_GLOBAL)
from pivy import coin  # noqa: E402 (after the flags, which the import's dlopen takes)

HEADER = "#Inventor V2.1 ascii\n"
VOLUMES = (HEADER + "Group {\n  CapsuleVolume {\n    fields [ SFString part, SFFloat r1e308 ]\n"
           '    part "head"\n  }\n  CapsuleVolume { fields [ SFString part ] part "neck" }\n}\n')


def load_guard(path):
    guard = ctypes.CDLL(path)
    guard.figment_guard_read_scene.argtypes = [ctypes.c_char_p, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_size_t]
    guard.figment_guard_check_shapes.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_size_t]
    return guard


def read_scene(guard, path, group):
    """0 and "", or 1 and the guard's one line."""
    error = ctypes.create_string_buffer(1024)
    status = guard.figment_guard_read_scene(path.encode(), ctypes.c_void_p(int(group.this)), error, len(error))
    return status, error.value.decode()


def check_shapes(guard, root):
    error = ctypes.create_string_buffer(1024)
    status = guard.figment_guard_check_shapes(ctypes.c_void_p(int(root.this)), error, len(error))
    return status, error.value.decode()


def expect(condition, what):
    if not condition:
        print("FAILED: " + what)
        sys.exit(1)


def main():
    guard = load_guard(sys.argv[1])
    folder = tempfile.mkdtemp(prefix="figment-pivy-")

    def write(name, text):
        path = os.path.join(folder, name)
        with open(path, "w") as out:
            out.write(text)
        return path

    write("volumes.iv", VOLUMES)
    bad = write("scene.iv", HEADER + 'Separator {\n  File { name "volumes.iv" }\n  Cube { }\n}\n')
    expect(not coin.SoType.fromName(coin.SbName("CapsuleVolume")).isBad(), "FIGMENT's nodes load by name")
    root = coin.SoSeparator()
    status, line = read_scene(guard, bad, root)
    print("bad scene: %d %s" % (status, line))
    expect(status == 1, "the issue 28 scene is refused")
    expect("\n" not in line and line.startswith("line 4: CapsuleVolume: fields [ SFFloat r1e308 ] declares a field "
                                                "CapsuleVolume does not have (in "), "one line naming line, node, field")
    expect(root.getNumChildren() == 0, "nothing added to the caller's group")

    good = write("good.iv", HEADER + "Separator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                 "  IndexedFaceSet { coordIndex [ 0 1 2 -1 ] }\n}\n")
    status, line = read_scene(guard, good, root)
    expect(status == 0 and line == "", "a good scene reads: " + line)
    expect(root.getNumChildren() == 1, "the scene is added to the caller's group")
    expect(check_shapes(guard, root) == (0, ""), "its shapes pass")

    faces = write("faces.iv", HEADER + "Separator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] }\n"
                  "  IndexedFaceSet { coordIndex [ 0 1 2147483647 -1 ] }\n}\n")
    drawn = coin.SoSeparator()
    expect(read_scene(guard, faces, drawn)[0] == 0, "a scene with a bad index reads")
    status, line = check_shapes(guard, drawn)
    print("bad shapes: %d %s" % (status, line))
    expect(status == 1 and line == "IndexedFaceSet: coordIndex[2] = 2147483647 is not a vertex: the coordinates have "
           "3 points", "its shapes are refused before drawing")
    print("ok")


if __name__ == "__main__":
    main()
