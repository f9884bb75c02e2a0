// What the OpenMesh and CGAL shims share, whatever library they wrap: the operator and
// workload codes of the C API (topolab's Operator::ALL and Workload order, the shims' shim.h),
// the harness's checksum mix, and the dispatch that gives each operator its own compiled loop.

#ifndef TOPOLAB_SHIM_OPERATORS_H
#define TOPOLAB_SHIM_OPERATORS_H

#include <cstdint>
#include <type_traits>

namespace topolab_shim {

// Operator codes: topolab's Operator::ALL order (shim.h).
enum Op {
  R00, R01, R02, R10, R11, R12, R20, R21, R22,
  BOUNDARY_VERTEX, BOUNDARY_EDGE, BOUNDARY_CURVES, EDGE_SUCCESSOR, EDGE_PREDECESSOR, OP_COUNT
};
enum Workload { CIRCULATORS, BARYCENTER, NORMALS, SMOOTHING, WORKLOAD_COUNT };

// harness/src/checksum.rs, bit for bit.
constexpr uint64_t mix(uint64_t a, uint64_t b) {
  const uint64_t h = (a * 0x9E3779B97F4A7C15ULL + b) * 0xBF58476D1CE4E5B9ULL;
  return h ^ (h >> 31);
}
static_assert(mix(3, 5) == 0x40159a6e5620edf9ULL, "mix differs from harness/src/checksum.rs");

// Runs f(std::integral_constant<int, op>) so each operator gets its own compiled loop.
template <class F> uint64_t dispatch(int op, F &&f) {
  switch (op) {
    case R00: return f(std::integral_constant<int, R00>{});
    case R01: return f(std::integral_constant<int, R01>{});
    case R02: return f(std::integral_constant<int, R02>{});
    case R10: return f(std::integral_constant<int, R10>{});
    case R11: return f(std::integral_constant<int, R11>{});
    case R12: return f(std::integral_constant<int, R12>{});
    case R20: return f(std::integral_constant<int, R20>{});
    case R21: return f(std::integral_constant<int, R21>{});
    case R22: return f(std::integral_constant<int, R22>{});
    case BOUNDARY_VERTEX: return f(std::integral_constant<int, BOUNDARY_VERTEX>{});
    case BOUNDARY_EDGE: return f(std::integral_constant<int, BOUNDARY_EDGE>{});
    case BOUNDARY_CURVES: return f(std::integral_constant<int, BOUNDARY_CURVES>{});
    case EDGE_SUCCESSOR: return f(std::integral_constant<int, EDGE_SUCCESSOR>{});
    case EDGE_PREDECESSOR: return f(std::integral_constant<int, EDGE_PREDECESSOR>{});
    default: return 0;
  }
}

}  // namespace topolab_shim

#endif
