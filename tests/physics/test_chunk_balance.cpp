// The threads' ranges of bar chunks follow their measured speeds
// (ChunkBalance): equal at first, about 1:2 after runs in which one thread
// took twice as long a particle, never below a quarter of an equal share,
// and unmoved by runs too short to time. (That a split never changes a
// number is test_threads.cpp's.)
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "model/model.hpp"
#include "physics/bar_chunks.hpp"
#include "physics/chunk_balance.hpp"

using namespace tendril;

namespace {

double particles_of(const BarChunks& B, const std::vector<std::uint32_t>& first, unsigned t) {
  const std::uint32_t a = first[t], b = first[t + 1];
  return a < b ? double(B.chunks[b - 1].particles_end - B.chunks[a].particles_begin) : 0.0;
}

// Runs under the current split in which thread t takes pace[t] seconds a particle.
void run(ChunkBalance& balance, const BarChunks& B, unsigned threads, const std::vector<double>& pace, int runs) {
  for (int r = 0; r < runs; ++r) {
    const std::vector<std::uint32_t>& first = balance.split(B, threads);
    std::vector<double> busy(threads);
    for (unsigned t = 0; t < threads; ++t) busy[t] = particles_of(B, first, t) * pace[t];
    balance.measured(B, busy);
  }
}

}  // namespace

TEST_CASE("chunk balance: the ranges follow the threads' speeds") {
  Model m;
  std::vector<ParticleId> g;
  const int s = 100;  // 10 000 particles: 10 chunks of 1024
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) g.push_back(m.add_particle(Vec3(c, r, 0)));
  m.add_quad_grid(g, s, s, Section{1e5, 0, 1e3, 0});
  BarChunks B;
  B.derive(m);
  REQUIRE(B.chunks.size() == 10);
  const double chunk = 1024, total = 10000;
  ChunkBalance balance;

  // Equal shares first: the boundary nearest 5000 (5120, not 4096).
  const std::vector<std::uint32_t> first = balance.split(B, 2);
  CHECK(particles_of(B, first, 0) == doctest::Approx(5120));
  CHECK(particles_of(B, first, 1) == doctest::Approx(total - 5120));

  // Runs too short to time (20 us a thread) move nothing.
  run(balance, B, 2, {2e-9, 1e-9}, 50);
  CHECK(particles_of(B, balance.split(B, 2), 0) == doctest::Approx(5120));

  // Thread 0 twice as slow a particle: a third of the particles, within a chunk.
  run(balance, B, 2, {2e-8, 1e-8}, 60);
  CHECK(std::abs(particles_of(B, balance.split(B, 2), 0) - total / 3) <= chunk / 2);

  // A thread 1000x slower keeps a quarter of an equal share (1250).
  run(balance, B, 2, {1e-5, 1e-8}, 60);
  CHECK(std::abs(particles_of(B, balance.split(B, 2), 0) - total / 8) <= chunk / 2);

  // Back to equal speeds on three threads: a third each, within a chunk
  // (each of its two boundaries within half a chunk).
  run(balance, B, 3, {1e-8, 1e-8, 1e-8}, 60);
  const std::vector<std::uint32_t> three = balance.split(B, 3);
  for (unsigned t = 0; t < 3; ++t) CHECK(std::abs(particles_of(B, three, t) - total / 3) <= chunk);
}
