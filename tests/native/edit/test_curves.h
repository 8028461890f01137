// Shared test curves of the edit tests: a wavy open polyline of uneven spacing and a closed loop.
#pragma once

#include <cmath>
#include <vector>

namespace edit_test {

// n points along a wave with uneven spacing (like a stroke drawn at varying speed).
inline std::vector<double> wave(int n) {
  std::vector<double> xy;
  double x = 0;
  for (int i = 0; i < n; ++i) {
    x += 1.0 + 0.8 * std::sin(0.7 * i);
    xy.push_back(x);
    xy.push_back(3.0 * std::sin(0.3 * x));
  }
  return xy;
}

// n points on an ellipse with uneven angular steps.
inline std::vector<double> loop(int n) {
  std::vector<double> xy;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979323846 * (i + 0.3 * std::sin(1.3 * i)) / n;
    xy.push_back(10 * std::cos(a));
    xy.push_back(6 * std::sin(a));
  }
  return xy;
}

}  // namespace edit_test
