// How to assemble gradients and Hessian diagonals in parallel without races, measured on real
// meshes (the 2-panel skirt template at 20 mm, 2k vertices; GarmentCode gc_0333 at 12 mm, 19k
// vertices), 1 and 2 threads, best of many evaluations (the machine may be shared):
//   springs  A. per-thread buffers: each thread scatters its block of springs into its own #V×6
//              buffer, then a pass over vertices sums the buffers (what engine/energy/assembler
//              does);
//            B. element results + incidence gather: one pass computes every spring once into an
//              array, a second pass lets every vertex gather its springs' results;
//            C. per-vertex recomputation: every vertex evaluates its own springs (each spring
//              twice), one pass, no buffers.
//   bending  D. per-stencil scatter into per-thread buffers;
//            E. the constant Hessian merged into one sparse matrix K, gathered per vertex (what
//              the assembler does for all quadratic potentials).
// Also the smallest domain for which a second thread pays off (kMinWorkPerBlock).
// Usage: bench_solver_assembly [DATA_DIR]

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "engine/core/mesh_topology.h"
#include "engine/energy/bending_potential.h"
#include "engine/pattern/garment_mesh.h"

using namespace garment;
using Clock = std::chrono::steady_clock;

namespace {

struct Spring {
  int i, j;
  double rest, stiffness;
};

// ½k(l − L)²: force on i and the PSD Hessian diagonal (as StretchPotential).
inline void spring(const double* xi, const double* xj, const Spring& s, double* force,
                   double* diagonal) {
  const double d[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double inverse = 1.0 / length;
  const double f = s.stiffness * (length - s.rest) * inverse;
  const double t = std::max(0.0, 1.0 - s.rest * inverse);
  const double along = s.stiffness * (1.0 - t) * inverse * inverse;
  for (int c = 0; c < 3; ++c) {
    force[c] = f * d[c];
    diagonal[c] = along * d[c] * d[c] + s.stiffness * t;
  }
}

struct Mesh {
  const char* name;
  int vertices = 0;
  std::vector<Spring> springs;
  std::vector<double> x;                      // #V×3
  std::vector<int> start, neighbour, spring;  // vertex → incident springs (CSR)
  std::vector<BendingStencil> stencils;
  std::vector<int> k_start, k_column;  // merged bending matrix, off-diagonal
  std::vector<double> k_value, k_diagonal;
};

Mesh make_mesh(const char* name, const Garment& garment) {
  Mesh mesh;
  mesh.name = name;
  mesh.vertices = garment.vertex_count();
  const MeshEdges edges = build_mesh_edges(garment.triangles, mesh.vertices);
  for (Eigen::Index e = 0; e < edges.edges.rows(); ++e) {
    const int i = edges.edges(e, 0), j = edges.edges(e, 1);
    mesh.springs.push_back(
        {i, j, (garment.rest_positions.row(i) - garment.rest_positions.row(j)).norm(), 1000.0});
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.002, 0.002);
  mesh.x.resize(3 * static_cast<std::size_t>(mesh.vertices));
  for (int v = 0; v < mesh.vertices; ++v) {
    mesh.x[3 * v] = 1.05 * garment.rest_positions(v, 0) + noise(rng);
    mesh.x[3 * v + 1] = 1.05 * garment.rest_positions(v, 1) + noise(rng);
    mesh.x[3 * v + 2] = 0.1 * garment.vertex_piece[v] + noise(rng);
  }
  mesh.start.assign(mesh.vertices + 1, 0);
  for (const Spring& s : mesh.springs)
    ++mesh.start[s.i + 1], ++mesh.start[s.j + 1];
  for (int v = 0; v < mesh.vertices; ++v)
    mesh.start[v + 1] += mesh.start[v];
  mesh.neighbour.resize(mesh.start.back());
  mesh.spring.resize(mesh.start.back());
  std::vector<int> cursor(mesh.start.begin(), mesh.start.end() - 1);
  for (int e = 0; e < static_cast<int>(mesh.springs.size()); ++e) {
    const Spring& s = mesh.springs[e];
    mesh.neighbour[cursor[s.i]] = s.j;
    mesh.spring[cursor[s.i]++] = e;
    mesh.neighbour[cursor[s.j]] = s.i;
    mesh.spring[cursor[s.j]++] = e;
  }
  mesh.stencils = interior_bending_stencils(garment);
  std::vector<std::vector<std::pair<int, double>>> rows(mesh.vertices);
  mesh.k_diagonal.assign(mesh.vertices, 0.0);
  for (const BendingStencil& stencil : mesh.stencils)
    for (int a = 0; a < stencil.count; ++a)
      for (int b = 0; b < stencil.count; ++b) {
        const double value = 1.5e-3 * stencil.weights[a] * stencil.weights[b];
        if (a == b)
          mesh.k_diagonal[stencil.vertices[a]] += value;
        else
          rows[stencil.vertices[a]].emplace_back(stencil.vertices[b], value);
      }
  mesh.k_start.push_back(0);
  for (auto& row : rows) {
    std::sort(row.begin(), row.end());
    for (std::size_t i = 0; i < row.size();) {
      const int column = row[i].first;
      double value = 0.0;
      for (; i < row.size() && row[i].first == column; ++i)
        value += row[i].second;
      mesh.k_column.push_back(column);
      mesh.k_value.push_back(value);
    }
    mesh.k_start.push_back(static_cast<int>(mesh.k_column.size()));
  }
  return mesh;
}

// Runs body(block) for blocks 0..B−1 on B threads (static partition), best time of `repeats`.
template <class Pass>
double best_seconds(int threads, int repeats, Pass&& pass) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto start = Clock::now();
    pass();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
  }
  return best;
}

template <class Block>
void for_blocks(int blocks, Block&& block) {
  if (blocks == 1)
    block(0);
  else
    tbb::parallel_for(0, blocks, block, tbb::static_partitioner());
}

struct Results {
  double seconds[2];  // 1 and 2 threads
};

void report(const char* what, const Mesh& mesh, const Results& r) {
  std::printf("  %-46s %8.1f us  %8.1f us  (%.2fx)   %5.1f ns per vertex on 1 thread\n", what,
              1e6 * r.seconds[0], 1e6 * r.seconds[1], r.seconds[0] / r.seconds[1],
              1e9 * r.seconds[0] / mesh.vertices);
}

void run(const Mesh& mesh, int repeats) {
  const int n = mesh.vertices;
  const int springs = static_cast<int>(mesh.springs.size());
  std::vector<double> out(6 * static_cast<std::size_t>(n));  // the gathered result
  std::printf("%s: %d vertices, %d springs, %zu bending stencils, %zu K entries\n", mesh.name, n,
              springs, mesh.stencils.size(), mesh.k_value.size());
  std::printf("  %-46s %11s %11s\n", "", "1 thread", "2 threads");

  Results a;
  for (int threads : {1, 2}) {
    std::vector<std::vector<double>> buffers(threads, std::vector<double>(6 * n, 0.0));
    a.seconds[threads - 1] = best_seconds(threads, repeats, [&] {
      for_blocks(threads, [&](int b) {
        double* buffer = buffers[b].data();
        for (int e = springs * b / threads; e < springs * (b + 1) / threads; ++e) {
          const Spring& s = mesh.springs[e];
          double f[3], d[3];
          spring(&mesh.x[3 * s.i], &mesh.x[3 * s.j], s, f, d);
          for (int c = 0; c < 3; ++c) {
            buffer[6 * s.i + c] += f[c];
            buffer[6 * s.j + c] -= f[c];
            buffer[6 * s.i + 3 + c] += d[c];
            buffer[6 * s.j + 3 + c] += d[c];
          }
        }
      });
      for_blocks(threads, [&](int b) {
        for (int v = n * b / threads; v < n * (b + 1) / threads; ++v)
          for (int c = 0; c < 6; ++c) {
            double sum = 0.0;
            for (auto& buffer : buffers)
              sum += std::exchange(buffer[6 * v + c], 0.0);
            out[6 * v + c] = sum;
          }
      });
    });
  }
  report("A springs: per-thread buffers + sum", mesh, a);

  Results b;
  std::vector<double> element(6 * static_cast<std::size_t>(springs));
  for (int threads : {1, 2}) {
    b.seconds[threads - 1] = best_seconds(threads, repeats, [&] {
      for_blocks(threads, [&](int block) {
        for (int e = springs * block / threads; e < springs * (block + 1) / threads; ++e) {
          const Spring& s = mesh.springs[e];
          spring(&mesh.x[3 * s.i], &mesh.x[3 * s.j], s, &element[6 * e], &element[6 * e + 3]);
        }
      });
      for_blocks(threads, [&](int block) {
        for (int v = n * block / threads; v < n * (block + 1) / threads; ++v) {
          double sum[6] = {0, 0, 0, 0, 0, 0};
          for (int q = mesh.start[v]; q < mesh.start[v + 1]; ++q) {
            const int e = mesh.spring[q];
            const double sign = mesh.springs[e].i == v ? 1.0 : -1.0;
            for (int c = 0; c < 3; ++c) {
              sum[c] += sign * element[6 * e + c];
              sum[3 + c] += element[6 * e + 3 + c];
            }
          }
          for (int c = 0; c < 6; ++c)
            out[6 * v + c] = sum[c];
        }
      });
    });
  }
  report("B springs: element results + incidence gather", mesh, b);

  Results c;
  for (int threads : {1, 2}) {
    c.seconds[threads - 1] = best_seconds(threads, repeats, [&] {
      for_blocks(threads, [&](int block) {
        for (int v = n * block / threads; v < n * (block + 1) / threads; ++v) {
          double sum[6] = {0, 0, 0, 0, 0, 0};
          for (int q = mesh.start[v]; q < mesh.start[v + 1]; ++q) {
            double f[3], d[3];
            spring(&mesh.x[3 * v], &mesh.x[3 * mesh.neighbour[q]], mesh.springs[mesh.spring[q]], f,
                   d);
            for (int k = 0; k < 3; ++k) {
              sum[k] += f[k];
              sum[3 + k] += d[k];
            }
          }
          for (int k = 0; k < 6; ++k)
            out[6 * v + k] = sum[k];
        }
      });
    });
  }
  report("C springs: per-vertex recomputation", mesh, c);

  Results d;
  const int stencils = static_cast<int>(mesh.stencils.size());
  for (int threads : {1, 2}) {
    std::vector<std::vector<double>> buffers(threads, std::vector<double>(3 * n, 0.0));
    d.seconds[threads - 1] = best_seconds(threads, repeats, [&] {
      for_blocks(threads, [&](int block) {
        double* buffer = buffers[block].data();
        for (int s = stencils * block / threads; s < stencils * (block + 1) / threads; ++s) {
          const BendingStencil& stencil = mesh.stencils[s];
          double sum[3] = {0, 0, 0};
          for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k)
              sum[k] += stencil.weights[i] * mesh.x[3 * stencil.vertices[i] + k];
          for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k)
              buffer[3 * stencil.vertices[i] + k] += 1.5e-3 * stencil.weights[i] * sum[k];
        }
      });
      for_blocks(threads, [&](int block) {
        for (int v = n * block / threads; v < n * (block + 1) / threads; ++v)
          for (int k = 0; k < 3; ++k) {
            double sum = 0.0;
            for (auto& buffer : buffers)
              sum += std::exchange(buffer[3 * v + k], 0.0);
            out[6 * v + k] = sum;
          }
      });
    });
  }
  report("D bending: per-stencil scatter + sum", mesh, d);

  Results e;
  for (int threads : {1, 2}) {
    e.seconds[threads - 1] = best_seconds(threads, repeats, [&] {
      for_blocks(threads, [&](int block) {
        for (int v = n * block / threads; v < n * (block + 1) / threads; ++v) {
          double even[3], odd[3] = {0, 0, 0};
          for (int k = 0; k < 3; ++k)
            even[k] = mesh.k_diagonal[v] * mesh.x[3 * v + k];
          int q = mesh.k_start[v];
          for (; q + 1 < mesh.k_start[v + 1]; q += 2)
            for (int k = 0; k < 3; ++k) {
              even[k] += mesh.k_value[q] * mesh.x[3 * mesh.k_column[q] + k];
              odd[k] += mesh.k_value[q + 1] * mesh.x[3 * mesh.k_column[q + 1] + k];
            }
          if (q < mesh.k_start[v + 1])
            for (int k = 0; k < 3; ++k)
              even[k] += mesh.k_value[q] * mesh.x[3 * mesh.k_column[q] + k];
          for (int k = 0; k < 3; ++k)
            out[6 * v + k] = even[k] + odd[k];
        }
      });
    });
  }
  report("E bending: merged K, per-vertex gather", mesh, e);
}

// Smallest domain worth two threads: strategy A on the first `n` vertices' springs.
void threshold(const Mesh& mesh) {
  std::printf("\nsecond thread break-even (strategy A on a sub-domain of %s):\n", mesh.name);
  for (int n : {128, 256, 512, 1024, 2048}) {
    std::vector<Spring> part;
    for (const Spring& s : mesh.springs)
      if (s.i < n && s.j < n) part.push_back(s);
    const int springs = static_cast<int>(part.size());
    double seconds[2];
    for (int threads : {1, 2}) {
      std::vector<std::vector<double>> buffers(threads, std::vector<double>(6 * n, 0.0));
      seconds[threads - 1] = best_seconds(threads, 4000, [&] {
        for_blocks(threads, [&](int b) {
          double* buffer = buffers[b].data();
          for (int e = springs * b / threads; e < springs * (b + 1) / threads; ++e) {
            double f[3], d[3];
            spring(&mesh.x[3 * part[e].i], &mesh.x[3 * part[e].j], part[e], f, d);
            for (int c = 0; c < 3; ++c) {
              buffer[6 * part[e].i + c] += f[c];
              buffer[6 * part[e].j + c] -= f[c];
            }
          }
        });
      });
    }
    std::printf("  %5d vertices, %5d springs: %7.1f us on 1 thread, %7.1f us on 2 (%.2fx)\n", n,
                springs, 1e6 * seconds[0], 1e6 * seconds[1], seconds[0] / seconds[1]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path data = argc > 1 ? argv[1] : GARMENT_SHARED_DATA;
  std::vector<Mesh> meshes;
  try {
    MeshingOptions small, fine;
    small.target_edge_length = 0.02;
    fine.target_edge_length = 0.012;
    meshes.push_back(
        make_mesh("2k (skirt_2_panels, 20 mm)",
                  build_garment(load_pattern(data / "patterns/pattern_generator_templates/"
                                                    "skirts__skirt_2_panels.json"),
                                small)));
    meshes.push_back(make_mesh(
        "20k (gc_0333, 12 mm)",
        build_garment(load_pattern(data / "patterns/garmentcode_random/gc_0333_specification.json"),
                      fine)));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "cannot load the benchmark patterns: %s\n", error.what());
    return 1;
  }
  run(meshes[0], 3000);
  std::printf("\n");
  run(meshes[1], 300);
  threshold(meshes[0]);
  return 0;
}
