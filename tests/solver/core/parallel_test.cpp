// TwoEndedChunks (core/parallel.hpp): the threaded force loop's outward pass relies on every chunk
// being taken exactly once, each thread's chunks forming one run, and met() naming the boundary.
#include "silodem/core/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace {

using silodem::TwoEndedChunks;

struct Taken {
  std::vector<std::size_t> by[2];
};

/// Two real threads, started together, drain n chunks, each spending about 5 µs per chunk so
/// that they interleave; thread 1 also waits `slow` per chunk (a slower core).
Taken drain(TwoEndedChunks& q, std::size_t n, std::chrono::microseconds slow) {
  q.reset(n);
  Taken t;
  std::atomic<int> ready{0};
  auto work = [&](int k) {
    ready.fetch_add(1);
    while (ready.load() < 2) {
    }
    for (std::size_t c; q.take(k, c);) {
      t.by[k].push_back(c);
      const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(5) + (k == 1 ? slow : slow * 0);
      while (std::chrono::steady_clock::now() < until) {
      }
    }
  };
  std::thread other(work, 1);
  work(0);
  other.join();
  return t;
}

TEST(TwoEndedChunks, EveryChunkOnceAsTwoRunsMeetingAtMet) {
  TwoEndedChunks q;
  int both = 0;  // runs where both threads took chunks (a descheduled thread may miss a run)
  for (int rep = 0; rep < 20; ++rep) {
    const std::size_t n = 1000 + std::size_t(rep);
    const Taken t = drain(q, n, std::chrono::microseconds(0));
    const std::size_t m = q.met();
    both += int(m > 0 && m < n);
    ASSERT_EQ(t.by[0].size(), m);
    ASSERT_EQ(t.by[1].size(), n - m);
    for (std::size_t k = 0; k < m; ++k) ASSERT_EQ(t.by[0][k], k);          // 0, 1, ..., m-1
    for (std::size_t k = 0; k < n - m; ++k) ASSERT_EQ(t.by[1][k], n - 1 - k);  // n-1, ..., m
  }
  EXPECT_GE(both, 10) << "the threads did not interleave: the test proved nothing";
}

TEST(TwoEndedChunks, TheFasterThreadTakesMore) {
  TwoEndedChunks q;
  const std::size_t n = 200;
  const Taken t = drain(q, n, std::chrono::microseconds(200));
  EXPECT_GT(q.met(), n / 2) << "thread 1 sleeps 200 us per chunk, thread 0 not at all";
  EXPECT_EQ(t.by[0].size() + t.by[1].size(), n);
}

TEST(TwoEndedChunks, NoChunksAndOneChunk) {
  TwoEndedChunks q;
  q.reset(0);
  std::size_t c = 99;
  EXPECT_FALSE(q.take(0, c));
  EXPECT_FALSE(q.take(1, c));
  EXPECT_EQ(q.met(), 0u);
  q.reset(1);
  EXPECT_TRUE(q.take(1, c));
  EXPECT_EQ(c, 0u);
  EXPECT_FALSE(q.take(0, c));
  EXPECT_EQ(q.met(), 0u);  // thread 1 did [0, 1)
  // Reusable: a new reset starts over.
  q.reset(3);
  EXPECT_TRUE(q.take(0, c));
  EXPECT_EQ(c, 0u);
  EXPECT_TRUE(q.take(1, c));
  EXPECT_EQ(c, 2u);
  EXPECT_TRUE(q.take(0, c));
  EXPECT_EQ(c, 1u);
  EXPECT_FALSE(q.take(1, c));
  EXPECT_EQ(q.met(), 2u);
}

}  // namespace
