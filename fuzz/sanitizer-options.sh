# The sanitizer runtime options of every instrumented run (scripts/test --sanitize, scripts/fuzz),
# sourced by those scripts. Any finding is fatal: ASan stops at its first report, UBSan
# (built with -fno-sanitize-recover) too, and a leak fails the program at exit.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:print_summary=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
