# figment::cdt: artem-ogre's CDT 2.0.1 (https://github.com/artem-ogre/CDT), the constrained
# Delaunay triangulation sim/pattern/PanelMesh cuts sewing-pattern panels with.
#
# Why CDT: it keeps the given boundary points exactly and adds no Steiner points on the
# constraint edges unless asked, so both sides of a seam keep the nodes the edge sampling
# gave them, node for node; it erases the triangles outside an outline (concave panels,
# darts' notches) by itself; it is header-only C++ (no build, no ABI), well kept and
# tested, under MPL-2.0 (its predicates.h: BSD-3-Clause, W. Lenthe; portable_nth_element:
# Apache-2.0 with LLVM exception), which a proprietary FIGMENT may use unchanged. Debian 12
# packages neither CDT nor poly2tri, and CGAL's 2-D triangulations are GPL.
#
# Where from: CDT's own releases are only on GitHub; the PyPI sdist of PythonCDT 2.0.2 ships
# CDT 2.0.1's sources, and every machine that builds FIGMENT reaches PyPI. The archive is
# fetched at configure time by version and SHA-256 into the build tree (never into the
# source tree), and only CDT's headers and licences are unpacked from it. To build offline,
# point FIGMENT_CDT_ARCHIVE at a copy of the same archive: its checksum is checked the same.

set(FIGMENT_CDT_ARCHIVE "" CACHE FILEPATH
  "pythoncdt-2.0.2.tar.gz already downloaded (empty: fetch it from PyPI at configure time)")

set(_cdt_url "https://files.pythonhosted.org/packages/0b/08/21a9533f8349de75025251592a0e54759044f7124dbb27f5d47fc9c83f9a/pythoncdt-2.0.2.tar.gz")
set(_cdt_sha256 "303832cae14a5ce90bb4bc696274c8add0f1f0b9bd4edb943e24fd10417036c4")
set(_cdt_root "pythoncdt-2.0.2/CDT/CDT")  # CDT 2.0.1 inside the sdist
set(_cdt_dir "${PROJECT_BINARY_DIR}/_deps/cdt-2.0.1")
# The unpacked headers are keyed by the archive's checksum: a change of version re-fetches.
set(_cdt_stamp "${_cdt_dir}/sha256.txt")

set(_cdt_have FALSE)
if(EXISTS "${_cdt_stamp}" AND EXISTS "${_cdt_dir}/include/CDT.h")
  file(READ "${_cdt_stamp}" _cdt_stamped)
  if(_cdt_stamped STREQUAL _cdt_sha256)
    set(_cdt_have TRUE)
  endif()
endif()

if(NOT _cdt_have)
  if(FIGMENT_CDT_ARCHIVE)
    set(_cdt_archive "${FIGMENT_CDT_ARCHIVE}")
    if(NOT EXISTS "${_cdt_archive}")
      message(FATAL_ERROR "FIGMENT_CDT_ARCHIVE: no file ${_cdt_archive}")
    endif()
    file(SHA256 "${_cdt_archive}" _cdt_actual)
    if(NOT _cdt_actual STREQUAL _cdt_sha256)
      message(FATAL_ERROR "FIGMENT_CDT_ARCHIVE: ${_cdt_archive} has SHA-256 ${_cdt_actual}, expected ${_cdt_sha256}")
    endif()
  else()
    set(_cdt_archive "${PROJECT_BINARY_DIR}/_deps/pythoncdt-2.0.2.tar.gz")
    message(STATUS "Fetching CDT 2.0.1 (PythonCDT 2.0.2 sdist) from PyPI")
    file(DOWNLOAD "${_cdt_url}" "${_cdt_archive}" EXPECTED_HASH SHA256=${_cdt_sha256} TLS_VERIFY ON
      STATUS _cdt_status)
    list(GET _cdt_status 0 _cdt_code)
    if(NOT _cdt_code EQUAL 0)
      list(GET _cdt_status 1 _cdt_message)
      message(FATAL_ERROR "CDT: downloading ${_cdt_url} failed (${_cdt_message}); "
        "download it elsewhere and configure with -DFIGMENT_CDT_ARCHIVE=/path/to/pythoncdt-2.0.2.tar.gz")
    endif()
  endif()
  set(_cdt_unpack "${PROJECT_BINARY_DIR}/_deps/cdt-unpack")
  file(REMOVE_RECURSE "${_cdt_unpack}" "${_cdt_dir}")
  file(ARCHIVE_EXTRACT INPUT "${_cdt_archive}" DESTINATION "${_cdt_unpack}"
    PATTERNS "${_cdt_root}/include" "${_cdt_root}/LICENSE*")
  if(NOT EXISTS "${_cdt_unpack}/${_cdt_root}/include/CDT.h")
    message(FATAL_ERROR "CDT: ${_cdt_archive} holds no ${_cdt_root}/include/CDT.h")
  endif()
  file(RENAME "${_cdt_unpack}/${_cdt_root}" "${_cdt_dir}")
  file(REMOVE_RECURSE "${_cdt_unpack}")
  file(WRITE "${_cdt_stamp}" "${_cdt_sha256}")
endif()

# Header-only: CDT.h includes its .hpp implementations unless CDT_USE_AS_COMPILED_LIBRARY.
# SYSTEM, so FIGMENT's warnings judge FIGMENT's code, not CDT's.
add_library(figment::cdt INTERFACE IMPORTED)
set_target_properties(figment::cdt PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${_cdt_dir}/include"
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${_cdt_dir}/include")
