# Checks the object files of the kernels' wider copies (src/CMakeLists.txt, colza_kernels_<isa>:
# the force loops and the integrator's ranges, compiled with -fno-weak): each may define, besides local symbols,
# only its entry point's namespace colza::kernels_<isa> as global code, and no weak or unique
# symbol but the exception personality's pointer (DW.ref.__gxx_personality_v0, the same data in
# every object file). A weak function there (an inline function or template instantiation
# compiled for that copy's instruction set) could be the one the linker keeps for every caller,
# and code built for AVX-512 would then run on CPUs without it (engine/force_loops_body.hpp).
# Common symbols (C: empty objects such as std::ranges' function objects) are data, allowed.
#   cmake -DNM=nm -DOBJECTS="a.o|b.o" -P kernel_objects_symbols.cmake
string(REPLACE "|" ";" objects "${OBJECTS}")
set(failures "")
foreach(object IN LISTS objects)
  get_filename_component(file "${object}" NAME)
  if(NOT file MATCHES "_(generic|avx2|avx512)\\.cpp\\.o(bj)?$")
    message(FATAL_ERROR "${object}: not an object file of a kernels' copy")
  endif()
  set(isa ${CMAKE_MATCH_1})
  string(LENGTH "kernels_${isa}" length)
  set(entry_prefix "_ZN5colza${length}kernels_${isa}")  # mangled colza::kernels_<isa>::
  execute_process(COMMAND ${NM} --defined-only "${object}" OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${object}")
  endif()
  string(REPLACE "\n" ";" lines "${symbols}")
  set(entries 0)
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^[0-9a-fA-F]* *([A-Za-z]) (.+)$")
      continue()
    endif()
    set(type ${CMAKE_MATCH_1})
    set(name ${CMAKE_MATCH_2})
    if(type MATCHES "^[WwVvui]$" AND NOT name STREQUAL "DW.ref.__gxx_personality_v0")
      string(APPEND failures "\n  ${file}: weak or unique symbol ${type} ${name}")
    elseif(type MATCHES "^[TDBRG]$")
      string(FIND "${name}" "${entry_prefix}" at)
      if(at EQUAL 0)
        math(EXPR entries "${entries} + 1")
      else()
        string(APPEND failures "\n  ${file}: global symbol ${type} ${name} outside colza::kernels_${isa}")
      endif()
    endif()
  endforeach()
  if(entries EQUAL 0)
    string(APPEND failures "\n  ${file}: no entry point in colza::kernels_${isa}")
  endif()
  message(STATUS "${file}: ${entries} global symbol(s) in colza::kernels_${isa}, no weak symbol")
endforeach()
if(failures)
  message(FATAL_ERROR "symbols that could hand a copy's code to other callers (c++filt reads them):${failures}")
endif()
