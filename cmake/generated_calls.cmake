# A list that grows by adding a file: every source FILE.cpp defines
# `TYPE FILE<suffix>()`; sets <prefix>_DECLARATIONS and <prefix>_CALLS in the
# caller's scope, one line per file in name order, for configure_file.
function(generated_calls prefix type suffix)
  set(sources ${ARGN})
  list(SORT sources)
  set(declarations "")
  set(calls "")
  foreach(source ${sources})
    get_filename_component(stem ${source} NAME_WE)
    string(APPEND declarations "${type} ${stem}${suffix}();\n")
    string(APPEND calls "      ${stem}${suffix}(),\n")
  endforeach()
  set(${prefix}_DECLARATIONS "${declarations}" PARENT_SCOPE)
  set(${prefix}_CALLS "${calls}" PARENT_SCOPE)
endfunction()
