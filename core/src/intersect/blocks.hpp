// convexloc (internal) — the dual batches' pipeline, for lines and planes alike: queries in
// blocks of kBatchBlock, the cells of the next block found and their records requested
// while the block before is answered, so the loads of one block overlap the exact work of
// the other.
#pragma once

#include <cstddef>
#include <cstdint>

namespace convexloc::detail {

// queries per block of a dual batch (its prefetch distance)
inline constexpr std::size_t kBatchBlock = 16;

// For queries 0 .. n-1: `aim(i, up, down)` finds query i's two cells and requests their
// records, false where it has none; `answer(i, up, down)` then answers it from them, with
// up = -1 where aim found none. Each query is aimed one block before it is answered.
template <class Aim, class Answer>
void inBlocks(std::size_t n, Aim&& aim, Answer&& answer) {
  std::int64_t cells[2][kBatchBlock][2];  // per block: each query's up and down cells
  const auto aimBlock = [&](std::size_t first, std::int64_t(*c)[2]) {
    for (std::size_t j = 0; j < kBatchBlock && first + j < n; ++j)
      if (!aim(first + j, c[j][0], c[j][1])) c[j][0] = -1;
  };
  aimBlock(0, cells[0]);
  for (std::size_t first = 0, b = 0; first < n; first += kBatchBlock, b ^= 1) {
    aimBlock(first + kBatchBlock, cells[b ^ 1]);
    for (std::size_t j = 0; j < kBatchBlock && first + j < n; ++j)
      answer(first + j, cells[b][j][0], cells[b][j][1]);
  }
}

}  // namespace convexloc::detail
