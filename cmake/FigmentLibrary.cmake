# figment_export_library(NAME): what each of FIGMENT's libraries says once it is added as
# figment_NAME: its alias figment::NAME (the name find_package(Figment) gives it, so the
# tree and an installed consumer link it alike) and its include folder, the source tree's
# root in the build and include/figment once installed ("sim/core/BoundaryLoops.h" either way).
function(figment_export_library name)
  add_library(figment::${name} ALIAS figment_${name})
  set_target_properties(figment_${name} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(figment_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/figment>)
endfunction()
