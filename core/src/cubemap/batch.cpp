// convexloc — the cube map's batch: blocks of points in stages, with AVX2 kernels for the
// aim and the radii where the CPU has them.
//
// The kernels compute exactly what the scalar aim() and radiiDecide() compute (the same
// operations in the same order, no FMA), so a point's answer does not depend on which path
// took it; every point they leave open goes through the scalar fromLeaf() or run().
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <limits>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "convexloc/batch.hpp"
#include "convexloc/locate3d.hpp"
#include "cubemap/index.hpp"
#include "cubemap/query.hpp"
#include "detail/batch_loop.hpp"
#include "detail/radii.hpp"
#include "detail/sinks3d.hpp"

namespace convexloc {
namespace {

// a lane or point without a base cell (the scalar code takes it)
constexpr std::uint32_t kNoCell = 0xffffffffu;

// the batch's state for one block of points, structure of arrays
constexpr std::size_t kAimBlock = 32;
struct AimBlock {
  std::uint32_t deepI[kAimBlock], deepJ[kAimBlock], node[kAimBlock];
  double d2[kAimBlock];
  int level[kAimBlock];  // node's quadtree level
};

// what the vector aim needs of the locator
struct AimParams {
  Vec3 centre;
  double deepScale, lastDeepIndex;
  std::uint32_t resolution;
  int deepestLevel;
};

#if defined(__x86_64__)
// The radii stage for 4 points: gathers each base node's two radii (bytes 8..15 of its
// 16), decides as detail::radiiDecide does (the same roundings, no FMA) and writes the
// verdict; lanes without a node, on an inner node (NaN radii) or between the radii are
// appended to `open`.
__attribute__((target("avx2"), always_inline)) inline void decide4(__m128i node, __m256d d2,
                                                                   const long long* radii,
                                                                   Location* o, std::size_t j,
                                                                   std::uint32_t* open,
                                                                   std::size_t& left) noexcept {
  const __m128i missing = _mm_cmpeq_epi32(node, _mm_set1_epi32(-1));
  // four 8-byte loads (node 0 for lanes without one) rather than a gather instruction,
  // whose latency the next stage would wait on
  alignas(16) std::uint32_t at[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(at), _mm_andnot_si128(missing, node));
  const __m256i pairs =
      _mm256_setr_epi64x(radii[2 * std::size_t{at[0]}], radii[2 * std::size_t{at[1]}],
                         radii[2 * std::size_t{at[2]}], radii[2 * std::size_t{at[3]}]);
  const __m256 both = _mm256_castsi256_ps(
      _mm256_permutevar8x32_epi32(pairs, _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7)));
  const __m256d in2 = _mm256_cvtps_pd(_mm256_castps256_ps128(both));
  const __m256d out2 = _mm256_cvtps_pd(_mm256_extractf128_ps(both, 1));
  const __m256d product = _mm256_mul_pd(_mm256_sub_pd(d2, in2), _mm256_sub_pd(d2, out2));
  const __m256d decided = _mm256_cmp_pd(product, _mm256_setzero_pd(), _CMP_GT_OQ);
  // Outside (2) beyond the outer radius, else Inside (0), as 4 bytes
  const __m128i verdict =
      _mm256_cvttpd_epi32(_mm256_and_pd(_mm256_cmp_pd(d2, out2, _CMP_GT_OQ), _mm256_set1_pd(2.0)));
  const __m128i bytes = _mm_packus_epi16(_mm_packus_epi32(verdict, verdict), verdict);
  const int four = _mm_cvtsi128_si32(bytes);
  std::memcpy(o + j, &four, 4);
  unsigned undecided = static_cast<unsigned>(_mm256_movemask_pd(decided)) ^ 0xfu;
  undecided |= static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(missing)));
  while (undecided) {
    open[left++] =
        static_cast<std::uint32_t>(j + static_cast<std::size_t>(__builtin_ctz(undecided)));
    undecided &= undecided - 1;
  }
}

// the radii stage over a block the aim has filled, 4 points at a time; returns how many
// points it did (a multiple of 4), the open count in `left`
__attribute__((target("avx2"))) std::size_t decideAvx2(const AimBlock& b, std::size_t m,
                                                       const void* nodes, Location* o,
                                                       std::uint32_t* open,
                                                       std::size_t& left) noexcept {
  const long long* radii = static_cast<const long long*>(nodes) + 1;
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4)
    decide4(_mm_loadu_si128(reinterpret_cast<const __m128i*>(b.node + j)),
            _mm256_loadu_pd(b.d2 + j), radii, o, j, open, left);
  return j;
}

// CubemapLocator::aim for 4 points at a time, in AVX2 (no FMA: every operation rounds as
// the scalar code does, so deepI, deepJ, the base cell and d2 are the scalar ones). Lanes the
// scalar code would not aim (not finite, too far, the centre, a reciprocal that overflows)
// get node kNoCell and go the scalar way. Returns how many points it did (a multiple of 4).
// The radii stage runs after it over the whole block, not 4 points at a time as each 4 are
// aimed: two short loops of independent iterations keep more points in flight than one
// long one.
__attribute__((target("avx2"))) std::size_t aimAvx2(const Vec3* p, std::size_t m,
                                                    const AimParams& a, AimBlock& b) noexcept {
  const __m256d cx = _mm256_set1_pd(a.centre.x), cy = _mm256_set1_pd(a.centre.y),
                cz = _mm256_set1_pd(a.centre.z);
  const __m256d sign = _mm256_set1_pd(-0.0),
                big = _mm256_set1_pd(std::numeric_limits<double>::max());
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0);
  const __m256d scale = _mm256_set1_pd(a.deepScale), last = _mm256_set1_pd(a.lastDeepIndex);
  const __m128i g = _mm_set1_epi32(static_cast<int>(a.resolution)),
                shift = _mm_cvtsi32_si128(a.deepestLevel);
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    // 4 points as 3 loads (x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3), regrouped by coordinate
    const double* q = &p[j].x;
    static_assert(sizeof(Vec3) == 3 * sizeof(double));
    const __m256d v0 = _mm256_loadu_pd(q), v1 = _mm256_loadu_pd(q + 4), v2 = _mm256_loadu_pd(q + 8);
    const __m256d xs = _mm256_permute4x64_pd(
        _mm256_blend_pd(_mm256_blend_pd(v0, v1, 0b0100), v2, 0b0010), _MM_SHUFFLE(1, 2, 3, 0));
    const __m256d ys = _mm256_permute4x64_pd(
        _mm256_blend_pd(_mm256_blend_pd(v0, v1, 0b1001), v2, 0b0100), _MM_SHUFFLE(2, 3, 0, 1));
    const __m256d zs = _mm256_permute4x64_pd(
        _mm256_blend_pd(_mm256_blend_pd(v0, v1, 0b0010), v2, 0b1001), _MM_SHUFFLE(3, 0, 1, 2));
    const __m256d dx = _mm256_sub_pd(xs, cx), dy = _mm256_sub_pd(ys, cy),
                  dz = _mm256_sub_pd(zs, cz);
    const __m256d ax = _mm256_andnot_pd(sign, dx), ay = _mm256_andnot_pd(sign, dy),
                  az = _mm256_andnot_pd(sign, dz);
    const __m256d finite = _mm256_cmp_pd(_mm256_add_pd(_mm256_add_pd(ax, ay), az), big, _CMP_LE_OQ);
    const __m256d xw =
        _mm256_and_pd(_mm256_cmp_pd(ax, ay, _CMP_GE_OQ), _mm256_cmp_pd(ax, az, _CMP_GE_OQ));
    const __m256d yw = _mm256_andnot_pd(xw, _mm256_cmp_pd(ay, az, _CMP_GE_OQ));
    const __m256d major = _mm256_blendv_pd(_mm256_blendv_pd(dz, dy, yw), dx, xw);
    const __m256d du = _mm256_blendv_pd(_mm256_blendv_pd(dx, dz, yw), dy, xw);
    const __m256d dv = _mm256_blendv_pd(_mm256_blendv_pd(dy, dx, yw), dz, xw);
    const __m256d inv = _mm256_div_pd(one, _mm256_andnot_pd(sign, major));
    const __m256d good = _mm256_and_pd(finite, _mm256_cmp_pd(inv, big, _CMP_LE_OQ));
    const __m256d s = _mm256_mul_pd(du, inv), t = _mm256_mul_pd(dv, inv);
    const __m256d d2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                     _mm256_mul_pd(dz, dz));
    // (s + 1) * scale clamped to the last index, then truncated: as the scalar min after
    // truncation, for values >= 0 (and for the tiny negatives of s = -1 - 1 ulp alike)
    const __m256d fx =
        _mm256_and_pd(good, _mm256_min_pd(_mm256_mul_pd(_mm256_add_pd(s, one), scale), last));
    const __m256d fy =
        _mm256_and_pd(good, _mm256_min_pd(_mm256_mul_pd(_mm256_add_pd(t, one), scale), last));
    const __m128i deepI = _mm256_cvttpd_epi32(fx), deepJ = _mm256_cvttpd_epi32(fy);
    const __m256d axis = _mm256_blendv_pd(_mm256_blendv_pd(two, one, yw), zero, xw);
    const __m256d negative = _mm256_and_pd(_mm256_cmp_pd(major, zero, _CMP_LT_OQ), one);
    const __m128i face = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_add_pd(axis, axis), negative));
    const __m128i row = _mm_add_epi32(_mm_mullo_epi32(face, g), _mm_srl_epi32(deepJ, shift));
    __m128i node =
        _mm_add_epi32(_mm_mullo_epi32(row, g), _mm_srl_epi32(deepI, shift));  // baseCellIndex
    // lanes not aimed: kNoCell (all bits set)
    const __m128i bad = _mm256_cvtpd_epi32(_mm256_andnot_pd(good, one));  // 1 where not good
    node = _mm_or_si128(node, _mm_sub_epi32(_mm_setzero_si128(), bad));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(b.deepI + j), deepI);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(b.deepJ + j), deepJ);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(b.node + j), node);
    _mm256_storeu_pd(b.d2 + j, d2);
  }
  return j;
}

#else
std::size_t aimAvx2(const Vec3*, std::size_t, const AimParams&, AimBlock&) noexcept {
  return 0;
}
std::size_t decideAvx2(const AimBlock&, std::size_t, const void*, Location*, std::uint32_t*,
                       std::size_t&) noexcept {
  return 0;
}
#endif

}  // namespace

void CubemapLocator::locate(std::span<const Vec3> points, std::span<Location> out) const noexcept {
  if (!centred_) {
    detail::locateEach(*this, points, out);
    return;
  }
  // Blocks of points in stages: aim each (4 at a time in AVX2 where the CPU has it) and
  // prefetch its base cell, then find each leaf and let its radii decide, prefetching the
  // lists of the points they leave open, then the face tests; the cache misses of a large
  // table overlap instead of following one another.
  const std::size_t n = std::min(points.size(), out.size());
  const bool vector = vectorBatches();
  const AimParams params{
      centre_, deepScale_,
      static_cast<double>((static_cast<std::uint64_t>(resolution_) << deepestLevel_) - 1),
      resolution_, deepestLevel_};
  // a node table that stays in the L2 cache needs no prefetch stage
  constexpr std::size_t kCachedTable = 512 * 1024;
  const bool prefetch = nodes_.size() * sizeof(Node) > kCachedTable;
  AimBlock b;
  std::uint32_t pending[kAimBlock];
  static_assert(sizeof(Node) == 16 && offsetof(Node, in2) == 8 && offsetof(Node, out2) == 12);
  for (std::size_t i0 = 0; i0 < n; i0 += kAimBlock) {
    const std::size_t m = std::min(kAimBlock, n - i0);
    const Vec3* p = points.data() + i0;
    Location* o = out.data() + i0;
    // the points two blocks ahead: with the table's misses in flight, the hardware's stream
    // prefetch alone does not keep up
    if (i0 + 3 * kAimBlock <= n)
      for (std::size_t byte = 0; byte < kAimBlock * sizeof(Vec3); byte += 64)
        __builtin_prefetch(reinterpret_cast<const char*>(p + 2 * kAimBlock) + byte);
    // aim (4 at a time in AVX2 where the CPU has it), then the base nodes' radii decide most
    // points, without a branch on the answer; the open ones (no node, an inner node,
    // between the radii) go on
    std::size_t left = 0, aimed = 0, decided = 0;
    if (vector) aimed = aimAvx2(p, m, params, b);
    for (std::size_t j = aimed; j < m; ++j) {
      Aim a;
      const bool ok = aim(p[j], a) > 0;
      b.deepI[j] = static_cast<std::uint32_t>(a.deepI);
      b.deepJ[j] = static_cast<std::uint32_t>(a.deepJ);
      b.node[j] = ok ? a.baseCell : kNoCell;
      b.d2[j] = a.d2;
    }
    if (prefetch)
      for (std::size_t j = 0; j < m; ++j)
        __builtin_prefetch(nodes_.data() + (b.node[j] == kNoCell ? 0 : b.node[j]));
    if (vector) decided = decideAvx2(b, m, nodes_.data(), o, pending, left);
    for (std::size_t j = decided; j < m; ++j) {
      const bool missing = b.node[j] == kNoCell;
      const Node& nd = nodes_[missing ? 0 : b.node[j]];
      o[j] = detail::insideOrOutside(b.d2[j] > static_cast<double>(nd.out2));
      pending[left] = static_cast<std::uint32_t>(j);
      left += missing | !detail::radiiDecide(b.d2[j], nd.in2, nd.out2);
    }
    // a refined base cell: step down one level and prefetch that child (a quadtree's second
    // miss would otherwise follow the first)
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      b.level[j] = 0;
      if (b.node[j] == kNoCell) continue;
      const Node& nd = nodes_[b.node[j]];
      if (nd.count != cubemap::kInner) {
        __builtin_prefetch(entries_.data() + nd.first);
        continue;
      }
      const int shift = deepestLevel_ - 1;
      b.node[j] = nd.first + ((b.deepJ[j] >> shift) & 1) * 2 + ((b.deepI[j] >> shift) & 1);
      b.level[j] = 1;
      __builtin_prefetch(nodes_.data() + b.node[j]);
    }
    for (std::size_t k = 0; k < left; ++k) {
      const std::size_t j = pending[k];
      detail::NoSink3D sink;
      if (b.node[j] == kNoCell) {
        o[j] = run(p[j], sink);
        continue;
      }
      int level = b.level[j];
      o[j] =
          fromLeaf(p[j], b.d2[j], nodes_[leafAt(b.deepI[j], b.deepJ[j], b.node[j], level)], sink);
    }
  }
}

}  // namespace convexloc
