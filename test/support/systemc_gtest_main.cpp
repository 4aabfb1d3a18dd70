// GoogleTest entry point for suites that link SystemC: libsystemc owns main() and calls
// sc_main(), so the tests run from there.
#include <gtest/gtest.h>

#include <systemc>

int sc_main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
