// convexloc-bench, predicates: orient3d and orient2d one call at a time, on points clearly
// off a face's plane (the filter decides) against points exactly on it (the filter cannot,
// and the exact stage runs). The faces and points are the same in each pair but for the
// point's offset, so the ratio of two figures is the exact stage's cost per point.
//
// Exact, three kinds: "lattice", points of a tilted lattice plane whose differences are exact
// doubles (CAD coordinates with few significant bits); "tails", points of the plane z = x
// (the line y = x) with full 53-bit coordinates in [-1, 1], whose differences carry rounding
// tails; both within the narrow-integer stage. "wide", the same plane with coordinates of
// magnitudes 2^-20 .. 2^20: too wide a span for 61-bit integers, so the expansions decide.
// "extreme", the lattice plane scaled by 2^1000 (coordinates near 2^980): beyond the reach of
// both, the multiprecision stage decides.
// Off, one more kind: "step", a point one to four subnormal steps off a face in the plane
// z = 0 (the line y = 0), a CAD part on its ground plane: the filter allows for underflow.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/predicates.hpp"

using namespace convexloc;

namespace {

// cases cycled through (a power of two)
constexpr std::size_t kCases = 4096;

struct Orient {
  Vec3 a, b, c, d;
};
struct Turn {
  Vec2 a, b, c;
};

enum class Kind { Off, Step, Lattice, Tails, Wide, Extreme };

// a random integer in [-n, n]
double integer(Rng& r, std::uint64_t n) {
  return static_cast<double>(r.below(2 * n + 1)) - static_cast<double>(n);
}

// a coordinate: uniform in [-1, 1], or (Wide) of magnitude 2^-20 .. 2^20
double coordinate(Rng& r, Kind kind) {
  if (kind != Kind::Wide) return r.uniform(-1, 1);
  return (r.below(2) ? -1 : 1) * std::ldexp(1 + r.uniform(), static_cast<int>(r.below(41)) - 20);
}

// a face (a, b, c) and a point d on its plane, or clearly off it
Orient orientCase(Rng& r, Kind kind) {
  if (kind == Kind::Step) {
    auto ground = [&] { return Vec3{integer(r, 1 << 13), integer(r, 1 << 13), 0.0}; };
    const double step = std::ldexp(static_cast<double>(1 + r.below(4)), -1074);
    return {ground(), ground(), ground(), {integer(r, 1 << 13), integer(r, 1 << 13), -step}};
  }
  if (kind == Kind::Tails || kind == Kind::Wide) {
    auto at = [&] {
      const double x = coordinate(r, kind);
      return Vec3{x, coordinate(r, kind), x};
    };
    return {at(), at(), at(), at()};
  }
  // the plane o + i e + j f, all integers times 2^-20: tilted, every coordinate exact
  const double o[3] = {integer(r, 1 << 24), integer(r, 1 << 24), integer(r, 1 << 24)};
  const double e[3] = {integer(r, 1 << 10), integer(r, 1 << 10), integer(r, 1 << 10)};
  const double f[3] = {integer(r, 1 << 10), integer(r, 1 << 10), integer(r, 1 << 10)};
  auto at = [&](double lift) {
    const double i = integer(r, 1 << 10), j = integer(r, 1 << 10);
    return Vec3{std::ldexp(o[0] + i * e[0] + j * f[0], -20),
                std::ldexp(o[1] + i * e[1] + j * f[1], -20),
                std::ldexp(o[2] + i * e[2] + j * f[2] + lift, -20)};
  };
  const double lift = kind == Kind::Off ? static_cast<double>(1 << 20) : 0.0;
  Orient out{at(0), at(0), at(0), at(lift)};
  if (kind == Kind::Extreme)  // a power of two keeps the point on the plane
    for (Vec3* v : {&out.a, &out.b, &out.c, &out.d})
      *v = {std::ldexp(v->x, 1000), std::ldexp(v->y, 1000), std::ldexp(v->z, 1000)};
  return out;
}

// three points on a line, or the third clearly off it
Turn turnCase(Rng& r, Kind kind) {
  if (kind == Kind::Step) {
    const double step = std::ldexp(static_cast<double>(1 + r.below(4)), -1074);
    return {{integer(r, 1 << 13), 0.0}, {integer(r, 1 << 13), 0.0}, {integer(r, 1 << 13), step}};
  }
  if (kind == Kind::Tails || kind == Kind::Wide) {
    auto at = [&] {
      const double x = coordinate(r, kind);
      return Vec2{x, x};
    };
    return {at(), at(), at()};
  }
  const Vec2 o{integer(r, 1 << 24), integer(r, 1 << 24)},
      e{integer(r, 1 << 10), integer(r, 1 << 10)};
  auto at = [&](double lift) {
    const double i = integer(r, 1 << 10);
    return Vec2{std::ldexp(o.x + i * e.x, -20), std::ldexp(o.y + i * e.y + lift, -20)};
  };
  const double lift = kind == Kind::Off ? static_cast<double>(1 << 20) : 0.0;
  Turn out{at(0), at(0), at(lift)};
  if (kind == Kind::Extreme)
    for (Vec2* v : {&out.a, &out.b, &out.c}) *v = {std::ldexp(v->x, 1000), std::ldexp(v->y, 1000)};
  return out;
}

template <class Case, class Make>
std::vector<Case> cases(Kind kind, Make make) {
  Rng r(7);
  std::vector<Case> out;
  for (std::size_t i = 0; i < kCases; ++i) out.push_back(make(r, kind));
  return out;
}

// the share of calls each exact stage decided since `from`
void stageCounters(benchmark::State& state, const ExactStageCounts& from) {
  const ExactStageCounts now = exactStageCounts();
  const double n = static_cast<double>(state.iterations());
  state.counters["narrow"] = static_cast<double>(now.narrowIntegers - from.narrowIntegers) / n;
  state.counters["expansions"] = static_cast<double>(now.expansions - from.expansions) / n;
  state.counters["multi"] = static_cast<double>(now.multiprecision - from.multiprecision) / n;
}

void orient3dBench(benchmark::State& state, Kind kind) {
  const std::vector<Orient> all = cases<Orient>(kind, orientCase);
  const ExactStageCounts before = exactStageCounts();
  std::size_t i = 0;
  for (auto _ : state) {
    const Orient& o = all[i];
    benchmark::DoNotOptimize(orient3d(o.a, o.b, o.c, o.d));
    i = (i + 1) & (kCases - 1);
  }
  state.SetItemsProcessed(state.iterations());
  stageCounters(state, before);
}

void orient2dBench(benchmark::State& state, Kind kind) {
  const std::vector<Turn> all = cases<Turn>(kind, turnCase);
  const ExactStageCounts before = exactStageCounts();
  std::size_t i = 0;
  for (auto _ : state) {
    const Turn& t = all[i];
    benchmark::DoNotOptimize(orient2d(t.a, t.b, t.c));
    i = (i + 1) & (kCases - 1);
  }
  state.SetItemsProcessed(state.iterations());
  stageCounters(state, before);
}

[[maybe_unused]] const bool registered = [] {
  const std::pair<const char*, Kind> kinds[] = {
      {"off", Kind::Off},          {"off_by_a_subnormal_step", Kind::Step},
      {"on_lattice", Kind::Lattice}, {"on_tails", Kind::Tails},
      {"on_wide", Kind::Wide},     {"on_extreme", Kind::Extreme}};
  for (auto [name, kind] : kinds) {
    benchmark::RegisterBenchmark((std::string("Orient3D/") + name).c_str(), orient3dBench, kind);
    benchmark::RegisterBenchmark((std::string("Orient2D/") + name).c_str(), orient2dBench, kind);
  }
  return true;
}();

}  // namespace
