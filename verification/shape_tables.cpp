// Fig. 4's tables (verification/shape_figures.sh): for linear, uGIMP and LME with gamma = 0.8, 1.8 and 4, the
// stencils of a 41 x 41 lattice of points on [-2, 2]^2 and of 1001 points on [-5, 5] (h = 1), each written as
// `mpm shape --dim D --kind KIND [--gamma G] --at ...` prints them: the same function (mpm::cli::evaluate_request of
// mpm/cli/shape_request.hpp, compiled by the library), the same CSV, byte for byte. A program of its own, so that make figures builds these
// in a few seconds instead of the whole command-line program.
//   build/bin/shape_tables DATA_DIR    writes DATA_DIR/shape2d_NAME.csv and shape1d_NAME.csv (NAME: linear, ugimp,
//                                       lme_0.8, lme_1.8, lme_4); exit 3 if one cannot be written
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/cli/shape_request.hpp"

namespace {

/// A coordinate as `mpm shape --at` reads it from shape_figures.sh's lattice: printed with %g, read back.
double as_printed(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return std::strtod(text, nullptr);
}

/// The points of Fig. 4: 41 x 41 on [-2, 2]^2 (x fastest) in 2D, 1001 on [-5, 5] in 1D.
std::vector<std::vector<double>> lattice(int dimension) {
  std::vector<std::vector<double>> points;
  if (dimension == 2) {
    for (int j = 0; j <= 40; ++j)
      for (int i = 0; i <= 40; ++i) points.push_back({as_printed(-2 + 0.1 * i), as_printed(-2 + 0.1 * j)});
  } else {
    for (int i = 0; i <= 1000; ++i) points.push_back({as_printed(-5 + 0.01 * i)});
  }
  return points;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: shape_tables DATA_DIR\n");
    return 2;
  }
  struct Kind {
    const char* name;
    const char* kind;
    double gamma;
  };
  const Kind kinds[] = {{"linear", "linear", 3.0}, {"ugimp", "ugimp", 3.0}, {"lme_0.8", "lme", 0.8},
                        {"lme_1.8", "lme", 1.8},   {"lme_4", "lme", 4.0}};
  for (const Kind& kind : kinds)
    for (int dimension : {2, 1}) {
      mpm::cli::ShapeRequest request;
      request.dimension = dimension;
      request.kind = kind.kind;
      request.gamma = kind.gamma;
      request.points = lattice(dimension);
      const std::string path = std::string(argv[1]) + "/shape" + std::to_string(dimension) + "d_" + kind.name + ".csv";
      std::ofstream out(path);
      dimension == 1 ? mpm::cli::evaluate_request<1>(request, out) : mpm::cli::evaluate_request<2>(request, out);
      out.close();
      if (!out) {
        std::fprintf(stderr, "shape_tables: %s: cannot write\n", path.c_str());
        return 3;
      }
    }
  return 0;
}
