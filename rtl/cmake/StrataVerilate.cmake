# strata_verilate(<target> PREFIX <V...> TOP <module> SOURCES <.sv...> [SYSTEMC] [TRACE] [SHARDS <n>]
#                 [VERILATOR_ARGS ...])
# Verilates at build time (not at configure time, unlike Verilator's own verilate()): a custom
# command runs rtl/cmake/verilate_step.cmake when a source changes, and <target> compiles the
# fixed shard files it writes. So an RTL edit that changes the set of files Verilator writes
# rebuilds correctly. The verilated C++ is compiled with STRATA_VERILATED_OPT (see
# rtl/CMakeLists.txt); <target> also gets Verilator's runtime and include directories. TRACE
# verilates with --trace (VCD of the internal signals; the runtime then includes the VCD writer):
# every model of one <target> must agree on it, as they share its runtime.
set(STRATA_VERILATE_STEP ${CMAKE_CURRENT_LIST_DIR}/verilate_step.cmake)

function(strata_verilate target)
  cmake_parse_arguments(V "SYSTEMC;TRACE" "PREFIX;TOP;SHARDS" "SOURCES;VERILATOR_ARGS" ${ARGN})
  if(NOT V_SHARDS)
    set(V_SHARDS 1)
  endif()
  set(base ${CMAKE_CURRENT_BINARY_DIR}/verilated/${V_PREFIX})
  set(mdir ${base}/gen)
  set(shard_dir ${base}/shards)
  if(V_SYSTEMC)
    set(mode --sc)
  else()
    set(mode --cc)
  endif()
  if(V_TRACE)
    set(trace 1)
    list(APPEND mode --trace)
  else()
    set(trace 0)
  endif()
  set(command ${VERILATOR_BIN} ${mode} --prefix ${V_PREFIX} --top-module ${V_TOP} ${V_VERILATOR_ARGS} ${V_SOURCES})
  # Rewritten only when the command changes, so a reconfigure does not re-verilate.
  file(CONFIGURE OUTPUT ${base}/args.cmake
       CONTENT "set(VERILATOR_COMMAND \"${command}\")\nset(VERILATOR_ROOT \"${VERILATOR_ROOT}\")\n" @ONLY)
  set(shards "")
  math(EXPR last "${V_SHARDS} - 1")
  foreach(i RANGE ${last})
    list(APPEND shards ${shard_dir}/${V_PREFIX}__shard${i}.cpp)
  endforeach()
  add_custom_command(
    OUTPUT ${shards} ${mdir}/${V_PREFIX}.h
    COMMAND ${CMAKE_COMMAND} -DARGS_FILE=${base}/args.cmake -DMDIR=${mdir} -DPREFIX=${V_PREFIX}
            -DSHARD_DIR=${shard_dir} -DSHARDS=${V_SHARDS} -DTRACE=${trace} -P ${STRATA_VERILATE_STEP}
    DEPENDS ${V_SOURCES} ${VERILATOR_BIN} ${base}/args.cmake ${STRATA_VERILATE_STEP}
    COMMENT "Verilating ${V_TOP} (${V_PREFIX})"
    VERBATIM)
  target_sources(${target} PRIVATE ${shards})
  set_source_files_properties(${shards} PROPERTIES COMPILE_OPTIONS "${STRATA_VERILATED_OPT}")
  target_include_directories(${target} PUBLIC ${mdir})
  get_target_property(has_runtime ${target} STRATA_VERILATED_RUNTIME)
  if(NOT has_runtime)
    set_target_properties(${target} PROPERTIES STRATA_VERILATED_RUNTIME ON)
    set(runtime ${VERILATOR_ROOT}/include/verilated.cpp ${VERILATOR_ROOT}/include/verilated_threads.cpp)
    if(V_TRACE)
      list(APPEND runtime ${VERILATOR_ROOT}/include/verilated_vcd_c.cpp)
    endif()
    target_sources(${target} PRIVATE ${runtime})
    set_source_files_properties(${runtime} PROPERTIES COMPILE_OPTIONS "${STRATA_VERILATED_OPT}")
    # Verilator's headers are not held to our warning flags.
    target_include_directories(${target} SYSTEM PUBLIC ${VERILATOR_ROOT}/include ${VERILATOR_ROOT}/include/vltstd)
    if(V_SYSTEMC)
      set(sc 1)
    else()
      set(sc 0)
    endif()
    target_compile_definitions(${target} PRIVATE VM_COVERAGE=0 VM_SC=${sc} VM_TRACE=${trace} VM_TRACE_FST=0
                               VM_TRACE_VCD=${trace})
    target_link_libraries(${target} PUBLIC Threads::Threads)
  endif()
endfunction()
