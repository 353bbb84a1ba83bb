// convexloc — the polar locator's batch: blocks of points through the table in stages, and
// the AVX2 kernels of its first two stages.
//
// Every lane of a kernel does the scalar code's operations in the same order with the same
// roundings (no FMA), so a batch answers exactly what locate() answers point by point.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "convexloc/batch.hpp"
#include "convexloc/locate2d.hpp"
#include "detail/radii.hpp"
#include "detail/sinks2d.hpp"
#include "polar/index.hpp"
#include "polar/query.hpp"

namespace convexloc {
namespace {

// what the vector cell index needs of the locator
struct PolarParams {
  Vec2 centre;
  double slabScale, lastSlab;
  std::int32_t base[8], step[8];
};

#if defined(__x86_64__)
// polar::cellIndex and the squared distance for 4 points at a time, in AVX2 (no FMA:
// every operation rounds as the scalar code does, so the cells are the scalar ones; lanes
// the scalar code gives -1 get -1). Returns how many points it did (a multiple of 4).
__attribute__((target("avx2"))) std::size_t polarAimAvx2(const Vec2* p, std::size_t m,
                                                         const PolarParams& a, std::int64_t* cell,
                                                         double* d2) noexcept {
  const __m256d cx = _mm256_set1_pd(a.centre.x), cy = _mm256_set1_pd(a.centre.y);
  const __m256d sign = _mm256_set1_pd(-0.0),
                inf = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  const __m256d qd = _mm256_set1_pd(a.slabScale), last = _mm256_set1_pd(a.lastSlab);
  const __m256i base = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a.base));
  const __m256i step = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a.step));
  const __m256i low32 = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);  // int64 lanes to int32
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    // 4 points as 2 loads (x0 y0 x1 y1 | x2 y2 x3 y3), regrouped by coordinate
    const double* q = &p[j].x;
    static_assert(sizeof(Vec2) == 2 * sizeof(double));
    const __m256d v0 = _mm256_loadu_pd(q), v1 = _mm256_loadu_pd(q + 4);
    const __m256d xs = _mm256_permute4x64_pd(_mm256_unpacklo_pd(v0, v1), _MM_SHUFFLE(3, 1, 2, 0));
    const __m256d ys = _mm256_permute4x64_pd(_mm256_unpackhi_pd(v0, v1), _MM_SHUFFLE(3, 1, 2, 0));
    const __m256d dx = _mm256_sub_pd(xs, cx), dy = _mm256_sub_pd(ys, cy);
    const __m256d ax = _mm256_andnot_pd(sign, dx), ay = _mm256_andnot_pd(sign, dy);
    const __m256d hi = _mm256_max_pd(ax, ay), lo = _mm256_min_pd(ax, ay);
    const __m256d good = _mm256_and_pd(_mm256_cmp_pd(_mm256_add_pd(ax, ay), inf, _CMP_LT_OQ),
                                       _mm256_cmp_pd(hi, zero, _CMP_NEQ_OQ));
    // lanes that are not good may divide 0 by 0: masked to 0 before converting
    const __m256d k =
        _mm256_and_pd(good, _mm256_min_pd(_mm256_mul_pd(_mm256_div_pd(lo, hi), qd), last));
    const __m128i slab = _mm256_cvttpd_epi32(k);
    // sign bits of dx and dy as 0 / 1 in 32-bit lanes (a lambda would lose the target)
    const __m128i sx = _mm256_castsi256_si128(
        _mm256_permutevar8x32_epi32(_mm256_srli_epi64(_mm256_castpd_si256(dx), 63), low32));
    const __m128i sy = _mm256_castsi256_si128(
        _mm256_permutevar8x32_epi32(_mm256_srli_epi64(_mm256_castpd_si256(dy), 63), low32));
    const __m128i steep =
        _mm256_cvttpd_epi32(_mm256_and_pd(_mm256_cmp_pd(ay, ax, _CMP_GT_OQ), one));
    const __m128i octant =
        _mm_or_si128(_mm_or_si128(_mm_slli_epi32(sx, 2), _mm_slli_epi32(sy, 1)), steep);
    const __m256i index = _mm256_castsi128_si256(octant);
    const __m128i b = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(base, index));
    const __m128i st = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(step, index));
    __m128i c = _mm_add_epi32(b, _mm_mullo_epi32(st, slab));
    const __m128i bad = _mm256_cvtpd_epi32(_mm256_andnot_pd(good, one));  // 1 where not good
    c = _mm_or_si128(c, _mm_sub_epi32(_mm_setzero_si128(), bad));         // -1 there
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(cell + j), _mm256_cvtepi32_epi64(c));
    _mm256_storeu_pd(d2 + j, _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)));
  }
  return j;
}

// for each 4-bit mask of open lanes, those lanes in order (then zeros)
struct LaneLists {
  alignas(16) std::uint32_t lanes[16][4] = {};
  constexpr LaneLists() {
    for (std::uint32_t mask = 0; mask < 16; ++mask) {
      std::uint32_t k = 0;
      for (std::uint32_t lane = 0; lane < 4; ++lane)
        if (mask >> lane & 1) lanes[mask][k++] = lane;
    }
  }
};
inline constexpr LaneLists kOpenLanes;

// cell `c`'s radii as one 64-bit word (in2 in the low half), copied rather than read through
// a pointer of another type
inline long long radiiWord(const void* radii, std::int64_t c) noexcept {
  long long w;
  std::memcpy(&w, static_cast<const char*>(radii) + 8 * c, sizeof w);
  return w;
}

// The radii stage of PolarLocator's batch for 4 points at a time, in AVX2. Each lane loads
// its cell's radii as one 64-bit word (in2 low, out2 high; 4 plain loads rather than a
// gather), widens both to double (exact, as the scalar casts)
// and forms radiiDecide's product and the verdict's comparison with the same roundings (no
// FMA), so every lane gets the scalar answer. Lanes with no cell read cell 0 and are open.
// Writes the 4 verdicts, appends the open lanes to `pending` at `left` and prefetches their
// offsets, as the scalar loop does; returns how many points it did (a multiple of 4).
__attribute__((target("avx2"))) std::size_t polarDecideAvx2(
    const std::int64_t* cell, const double* d2, std::size_t m, const void* radii,
    const std::uint32_t* offsets, Location* o, std::uint32_t* pending, std::size_t& left) noexcept {
  // a local count: `left` itself might alias the stores through `pending` and `o`, which
  // would keep it in memory and chain every group to the previous one's store
  std::size_t open = left;
  const __m256i halves = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);  // in2 x4 | out2 x4
  const __m256d zero = _mm256_setzero_pd();
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    std::int64_t c[4];
    for (int k = 0; k < 4; ++k) c[k] = std::max<std::int64_t>(cell[j + k], 0);
    const __m256i r = _mm256_permutevar8x32_epi32(
        _mm256_setr_epi64x(radiiWord(radii, c[0]), radiiWord(radii, c[1]), radiiWord(radii, c[2]),
                           radiiWord(radii, c[3])),
        halves);
    const __m256d in2 = _mm256_cvtps_pd(_mm_castsi128_ps(_mm256_castsi256_si128(r)));
    const __m256d out2 = _mm256_cvtps_pd(_mm_castsi128_ps(_mm256_extracti128_si256(r, 1)));
    const __m256d d = _mm256_loadu_pd(d2 + j);
    // the verdicts' 4 bits spread to the low bit of 4 bytes, times 2: Inside 0, Outside 2
    const auto farther =
        static_cast<std::uint32_t>(_mm256_movemask_pd(_mm256_cmp_pd(d, out2, _CMP_GT_OQ)));
    const std::uint32_t verdicts = (farther * 0x204081u & 0x01010101u) * 2;
    static_assert(sizeof(Location) == 1);
    std::memcpy(o + j, &verdicts, 4);
    // open: no cell, or not decided (a NaN product compares false, as in the scalar code)
    const __m256d decided = _mm256_cmp_pd(
        _mm256_mul_pd(_mm256_sub_pd(d, in2), _mm256_sub_pd(d, out2)), zero, _CMP_GT_OQ);
    const __m256i ci = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cell + j));
    const __m256i none = _mm256_cmpgt_epi64(_mm256_setzero_si256(), ci);
    const auto lanes = static_cast<std::uint32_t>((_mm256_movemask_pd(decided) ^ 15) |
                                                  _mm256_movemask_pd(_mm256_castsi256_pd(none)));
    // a 16-byte store of the open lanes' indices: open never passes j, so it stays in the block
    const __m128i list = _mm_load_si128(reinterpret_cast<const __m128i*>(kOpenLanes.lanes[lanes]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(pending + open),
                     _mm_add_epi32(list, _mm_set1_epi32(static_cast<int>(j))));
    open += static_cast<std::size_t>(__builtin_popcount(lanes));
    for (int k = 0; k < 4; ++k) __builtin_prefetch(offsets + (lanes >> k & 1 ? c[k] : 0));
  }
  left = open;
  return j;
}
#else
std::size_t polarAimAvx2(const Vec2*, std::size_t, const PolarParams&, std::int64_t*,
                         double*) noexcept {
  return 0;
}
std::size_t polarDecideAvx2(const std::int64_t*, const double*, std::size_t, const void*,
                            const std::uint32_t*, Location*, std::uint32_t*,
                            std::size_t&) noexcept {
  return 0;
}
#endif

}  // namespace

void PolarLocator::locate(std::span<const Vec2> points, std::span<Location> out) const noexcept {
  // Blocks of points go through the table in stages (cell radii, then for the points they do
  // not decide the cell's run, then its edges), prefetching each stage's memory for the
  // whole block before the next stage reads it, so that the cache misses of a large table
  // overlap instead of following one another.
  constexpr std::size_t kBlock = 32;
  const std::size_t n = std::min(points.size(), out.size());
  std::int64_t cell[kBlock];
  double dist2[kBlock];
  std::uint32_t first[kBlock], count[kBlock], pending[kBlock];
  const bool vector = vectorBatches();
  // The radii prefetch pass runs only where the radii outgrow a typical L2 (1 MiB): below
  // that the vector stage's loads hit it anyway and the pass costs more than it hides. The
  // scalar stage always runs it.
  const bool prefetchRadii = !vector || radii_.size() * sizeof(Radii) > (std::size_t{1} << 20);
  PolarParams params{
      index_.centre, index_.slabScale, static_cast<double>(index_.slabsPerOctant - 1), {}, {}};
  for (int i = 0; i < 8; ++i) {
    params.base[i] = static_cast<std::int32_t>(index_.cellBase[i]);
    params.step[i] = static_cast<std::int32_t>(index_.cellStep[i]);
  }
  for (std::size_t i0 = 0; i0 < n; i0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - i0);
    const Vec2* p = points.data() + i0;
    Location* o = out.data() + i0;
    for (std::size_t j = vector ? polarAimAvx2(p, m, params, cell, dist2) : 0; j < m; ++j) {
      cell[j] = polar::cellIndex(index_, p[j]);
      dist2[j] = polar::distance2(p[j], index_.centre);
    }
    if (prefetchRadii)
      for (std::size_t j = 0; j < m; ++j)
        if (cell[j] >= 0) __builtin_prefetch(radii_.data() + cell[j]);
    // Without a branch on the answer (inside or outside come at random): every point writes
    // its radius verdict and its index, and only the open ones (between the radii, or with
    // no cell) advance the list of those left for the next stages.
    std::size_t left = 0, decided = 0;
    if (vector) {
      static_assert(sizeof(Radii) == 8 && offsetof(Radii, in2) == 0 && offsetof(Radii, out2) == 4);
      decided = polarDecideAvx2(cell, dist2, m, radii_.data(), offsets_.data(), o, pending, left);
    }
    for (std::size_t j = decided; j < m; ++j) {
      const std::size_t c = cell[j] >= 0 ? static_cast<std::size_t>(cell[j]) : 0;
      const Radii r = radii_[c];
      const double d2 = dist2[j];
      o[j] = detail::insideOrOutside(d2 > static_cast<double>(r.out2));
      const bool open = (cell[j] < 0) | !detail::radiiDecide(d2, r.in2, r.out2);
      pending[left] = static_cast<std::uint32_t>(j);
      left += open;
      __builtin_prefetch(offsets_.data() + (open ? c : 0));
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      first[j] = 0;
      count[j] = 0;
      if (cell[j] < 0) continue;
      first[j] = offsets_[static_cast<std::size_t>(cell[j])];
      count[j] = offsets_[static_cast<std::size_t>(cell[j]) + 1] - first[j];
      __builtin_prefetch(entries_.data() + first[j]);
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      if (count[j] - 1 >= 2) continue;
      first[j] = entries_[first[j]];  // now the first edge
      __builtin_prefetch(vertices_.data() + first[j]);
      __builtin_prefetch(vertices_.data() + first[j] + 2);
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      Location r;
      if (count[j] - 1 < 2 && polar::twoEdges(vertices_.data() + first[j], p[j], r)) {
        o[j] = r;
      } else {
        detail::NoSink2D sink;
        o[j] = run(p[j], sink);
      }
    }
  }
}

}  // namespace convexloc
