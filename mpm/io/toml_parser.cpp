/// \file
/// toml++'s parser (Debian's libtomlplusplus-dev), compiled once for every program that reads scenes,
/// not in every unit that includes mpm/io/scene_file.hpp (TOML_HEADER_ONLY 0 there).
#define TOML_IMPLEMENTATION
#include "mpm/io/scene_file.hpp"
