/// \file
/// The test program's entry point: doctest's own main(), with its command-line options.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
