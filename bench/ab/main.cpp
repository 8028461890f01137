// `npm run bench:ab` driver: the same curves traced by two builds of the surface core (A: a git
// ref, B: the working tree) in one process, in turn and alternating which goes first, so that both
// meet the same machine: this 2-core VM drifts by up to 25% between whole benchmark runs, which
// buries a change of a few percent. Prints one JSON line: per-curve best times over the rounds,
// their medians, the median of the per-curve ratios B/A, and mean curve lengths.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

extern "C" {
void* ab_init_A(const char*, const char*, const char*);
int ab_curves_A(void*);
double ab_trace_A(void*, int, double*);
void* ab_init_B(const char*, const char*, const char*);
int ab_curves_B(void*);
double ab_trace_B(void*, int, double*);
}

static double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x.empty() ? 0 : x[x.size() / 2];
}

int main(int argc, char** argv) {
  if (argc < 5) {
    fprintf(stderr, "usage: ab <mesh.bin> <points.bin> <curves> <rounds> [guide.bin]\n");
    return 2;
  }
  const char* guide = argc > 5 ? argv[5] : nullptr;
  void* a = ab_init_A(argv[1], argv[2], guide);
  void* b = ab_init_B(argv[1], argv[2], guide);
  if (!a || !b) return 1;
  const int n = std::min({ab_curves_A(a), ab_curves_B(b), atoi(argv[3])});
  const int rounds = std::max(1, atoi(argv[4]));
  std::vector<double> ta(n, 1e300), tb(n, 1e300), la(n), lb(n);
  for (int r = 0; r < rounds; ++r) {
    for (int i = 0; i < n; ++i) {
      double x, y;
      if ((i + r) % 2) {
        y = ab_trace_B(b, i, &lb[i]);
        x = ab_trace_A(a, i, &la[i]);
      } else {
        x = ab_trace_A(a, i, &la[i]);
        y = ab_trace_B(b, i, &lb[i]);
      }
      ta[i] = std::min(ta[i], x);
      tb[i] = std::min(tb[i], y);
    }
  }
  std::vector<double> ratio(n);
  double sa = 0, sb = 0, mla = 0, mlb = 0;
  int changed = 0;
  for (int i = 0; i < n; ++i) {
    ratio[i] = tb[i] / ta[i];
    sa += ta[i], sb += tb[i], mla += la[i] / n, mlb += lb[i] / n;
    changed += la[i] != lb[i];
  }
  printf(
      "{\"curves\":%d,\"rounds\":%d,\"median_a_ms\":%.4f,\"median_b_ms\":%.4f,\"median_ratio\":%.4f,"
      "\"total_ratio\":%.4f,\"mean_length_a\":%.10f,\"mean_length_b\":%.10f,\"curves_changed\":%d}\n",
      n, rounds, median(ta), median(tb), median(ratio), sb / sa, mla, mlb, changed);
}
