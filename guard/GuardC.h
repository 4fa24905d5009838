#pragma once
/* The guard's two calls (guard/Guard.h) for C, and for Python through ctypes beside pivy, which
   shares the program's Coin: libfigment_guard.so exports them unmangled.

     import ctypes
     from pivy import coin
     guard = ctypes.CDLL("libfigment_guard.so")
     error = ctypes.create_string_buffer(1024)
     root = coin.SoSeparator()
     if guard.figment_guard_read_scene(b"scene.iv", ctypes.c_void_p(int(root.this)), error, 1024):
         raise SystemExit(error.value.decode())

   Nothing escapes either call (an exception becomes its one line). */

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Reads the scene in `path` as figment::guard::readScene does (initialising Coin first if the
   program has not) and, when it passes, adds its root to `group`, an SoGroup* (pivy:
   int(group.this)); a null `group` only checks. Returns 0, or 1 with one line in `error` (cut to
   `size` bytes with its terminating NUL; none is written when `error` is null). */
int figment_guard_read_scene(const char* path, void* group, char* error, size_t size);

/* Checks the shapes under `root`, an SoNode*, as figment::guard::checkShapes does: call it after
   evaluating what feeds them, before drawing. Returns 0, or 1 with one line in `error`. */
int figment_guard_check_shapes(void* root, char* error, size_t size);

#ifdef __cplusplus
}
#endif
