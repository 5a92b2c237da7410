// The distance-field cache under damage and growth (issue 40, item 6): a header altered on disk,
// a file truncated while a run uses it, the size limit with least-recently-used eviction, and the
// temporaries and partial files that killed runs leave behind. The fields are compared with a
// fresh build (never with the cache's own reading of itself). Real bodies (tests/data/bodies)
// where the field matters, two boxes where only the files do.

#include <sys/wait.h>
#include <unistd.h>

#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/body/body_mesh.h"
#include "engine/body/body_surface.h"
#include "engine/body/distance_grid_cache.h"
#include "engine/body/signed_distance_field.h"
#include "engine/core/hash64.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

// 10 mm instead of the default 6 mm: a real body builds in about a second, and nothing here
// depends on the accuracy.
constexpr double kBodySpacing = 0.01;

BodyMesh real_body(const char* name) {
  return load_body_obj(test::test_data(std::string("bodies/") + name + ".obj"));
}

// Two boxes: a field in milliseconds, for the tests about files rather than values.
BodyMesh two_boxes() {
  BodyMesh mesh;
  mesh.source = "boxes";
  mesh.vertices.resize(16, 3);
  mesh.triangles.resize(24, 3);
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const Eigen::Vector3d lows[2] = {{0.0, 0.0, 0.0}, {0.15, 0.0, 0.0}};
  const Eigen::Vector3d highs[2] = {{0.1, 0.3, 0.1}, {0.25, 0.3, 0.1}};
  for (int b = 0; b < 2; ++b) {
    for (int v = 0; v < 8; ++v)
      mesh.vertices.row(8 * b + v) =
          Eigen::Vector3d(v & 1 ? highs[b].x() : lows[b].x(), v & 2 ? highs[b].y() : lows[b].y(),
                          v & 4 ? highs[b].z() : lows[b].z());
    for (int f = 0; f < 6; ++f) {
      const int* q = faces[f];
      mesh.triangles.row(12 * b + 2 * f) =
          Eigen::Vector3i(8 * b + q[0], 8 * b + q[1], 8 * b + q[2]);
      mesh.triangles.row(12 * b + 2 * f + 1) =
          Eigen::Vector3i(8 * b + q[0], 8 * b + q[2], 8 * b + q[3]);
    }
  }
  validate_and_orient_body(mesh);
  return mesh;
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

template <typename T>
bool same_bytes(const SharedArray<T>& a, const SharedArray<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

bool same_lists(const CellTriangleLists& a, const CellTriangleLists& b) {
  return a.cells == b.cells && a.blocks == b.blocks && same_bytes(a.block_of, b.block_of) &&
         same_bytes(a.starts, b.starts) && same_bytes(a.entries, b.entries) &&
         same_bytes(a.triangle_outside, b.triangle_outside);
}

// The same field byte for byte: placement, samples and the exact cells' triangle lists.
bool same_field(const DistanceGrid& a, const DistanceGrid& b) {
  return a.origin == b.origin && a.spacing == b.spacing && a.size == b.size &&
         same_bytes(a.values, b.values) && a.surface && b.surface &&
         same_lists(a.surface->lists(), b.surface->lists());
}

// Where the 8 bytes of `value` first occur among the first `within` bytes of `bytes`.
std::size_t find_double(const std::string& bytes, double value, std::size_t within) {
  const std::string pattern(reinterpret_cast<const char*>(&value), sizeof value);
  const std::size_t at = bytes.substr(0, within).find(pattern);
  return at;
}

// A process id that no process has any longer: a child that has exited and been reaped.
pid_t dead_process_id() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  waitpid(child, &status, 0);
  return child;
}

void set_age(const std::filesystem::path& path, std::chrono::seconds age) {
  std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now() - age);
}

}  // namespace

class DistanceCacheTest : public QObject {
  Q_OBJECT

 private slots:
  // (a) The header places the samples in space. An altered spacing or origin used to pass (the
  // checksum covered the samples only): the field was used shifted or scaled, and the file was
  // never replaced.
  void altered_header_is_detected_rebuilt_and_replaced() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    SignedDistanceOptions options;
    options.spacing = kBodySpacing;
    options.cache_directory = folder.path().toStdString();
    const BodyMesh body = real_body("f_smpl_average_A40");
    const DistanceGrid fresh = compute_signed_distance_grid(body, options.spacing, options.margin);

    const SignedDistanceField written = signed_distance_field(body, options);
    QVERIFY(!written.from_cache);
    QVERIFY(same_field(written.grid, fresh));
    const std::string good = file_bytes(written.cache_file);
    // A valid file gives back the fresh build byte for byte.
    const SignedDistanceField hit = signed_distance_field(body, options);
    QVERIFY(hit.from_cache);
    QVERIFY(same_field(hit.grid, fresh));

    struct Alteration {
      const char* what;
      double stored, altered;
    };
    const Alteration alterations[] = {
        {"spacing +5 %", fresh.spacing, fresh.spacing * 1.05},
        {"origin x +1 cm", fresh.origin.x(), fresh.origin.x() + 0.01},
        {"origin y -2 cm", fresh.origin.y(), fresh.origin.y() - 0.02},
        {"origin z +1 mm", fresh.origin.z(), fresh.origin.z() + 0.001},
    };
    for (const Alteration& alteration : alterations) {
      std::string bytes = good;
      const std::size_t at = find_double(bytes, alteration.stored, 256);
      QVERIFY2(at != std::string::npos, alteration.what);
      std::memcpy(&bytes[at], &alteration.altered, sizeof(double));
      write_bytes(written.cache_file, bytes);

      const SignedDistanceField after = signed_distance_field(body, options);
      QVERIFY2(!after.from_cache, alteration.what);
      QVERIFY2(same_field(after.grid, fresh), alteration.what);
      // Replaced by the rebuilt field, which the next run reads.
      QVERIFY2(file_bytes(written.cache_file) == good, alteration.what);
      const SignedDistanceField next = signed_distance_field(body, options);
      QVERIFY2(next.from_cache && same_field(next.grid, fresh), alteration.what);
    }
  }

  // (b) A run that has read the field keeps it whatever happens to the file: truncating it in
  // place (a user's cleanup, `truncate`, another tool) used to kill the run with SIGBUS at its
  // next look at a sample, the field being a view of the file's mapping.
  void truncation_while_in_use_cannot_kill_the_run() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    SignedDistanceOptions options;
    options.spacing = kBodySpacing;
    options.cache_directory = folder.path().toStdString();
    const BodyMesh body = real_body("m_smpl_average_A40");
    const DistanceGrid fresh = compute_signed_distance_grid(body, options.spacing, options.margin);
    const std::filesystem::path file = signed_distance_field(body, options).cache_file;
    QVERIFY(std::filesystem::file_size(file) > 1000000);
    const std::uint64_t key = distance_grid_cache_key(body, options.spacing, options.margin);

    // In a child process, so that a signal fails this test instead of ending it: the child reads
    // the file as a run does, the file is truncated, and the child reads every sample and list.
    const pid_t child = fork();
    QVERIFY(child >= 0);
    if (child == 0) {
      // QtTest's handlers would report a fault as this test's crash; the parent reports it.
      std::signal(SIGBUS, SIG_DFL);
      std::signal(SIGSEGV, SIG_DFL);
      const std::optional<CachedDistanceGrid> cached = read_distance_grid_cache(file, key);
      if (!cached) _exit(3);
      std::error_code error;
      std::filesystem::resize_file(file, 0, error);
      if (error) _exit(4);
      const bool same = same_bytes(cached->grid.values, fresh.values) &&
                        same_lists(cached->lists, fresh.surface->lists());
      _exit(same ? 0 : 5);
    }
    int status = 0;
    QCOMPARE(waitpid(child, &status, 0), child);
    QVERIFY2(!WIFSIGNALED(status), qPrintable(QString("the reader was killed by signal %1 (%2)")
                                                  .arg(WTERMSIG(status))
                                                  .arg(strsignal(WTERMSIG(status)))));
    QVERIFY(WIFEXITED(status));
    QCOMPARE(WEXITSTATUS(status), 0);
    QCOMPARE(std::filesystem::file_size(file), std::uintmax_t{0});

    // The whole path in this process: the emptied file is rebuilt; a field read from the cache
    // answers as the fresh one after its file is cut in half.
    QVERIFY(!signed_distance_field(body, options).from_cache);
    const SignedDistanceField in_use = signed_distance_field(body, options);
    QVERIFY(in_use.from_cache);
    std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
    QVERIFY(same_field(in_use.grid, fresh));
    for (double z = -0.3; z <= 0.3; z += 0.01) {
      const Eigen::Vector3d point(0.0, 1.2, z);
      QCOMPARE(in_use.grid.value(point), fresh.value(point));
    }
    const SignedDistanceField after = signed_distance_field(body, options);
    QVERIFY(!after.from_cache);
    QVERIFY(same_field(after.grid, fresh));
  }

  // (c) The cache keeps to its limit ($GARMENT_CACHE_LIMIT here): a new file evicts the least
  // recently used ones (a hit counts as a use), never the file just read or written, even when
  // that file alone is over the limit.
  void cache_keeps_to_its_limit_evicting_the_least_recently_used() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    SignedDistanceOptions options;
    options.cache_directory = folder.path().toStdString();
    const BodyMesh body = two_boxes();
    auto field_at = [&](double spacing) {
      SignedDistanceOptions at = options;
      at.spacing = spacing;
      return signed_distance_field(body, at);
    };
    qunsetenv("GARMENT_CACHE_LIMIT");
    const std::filesystem::path a = field_at(0.020).cache_file;
    const std::filesystem::path b = field_at(0.021).cache_file;
    QVERIFY(std::filesystem::exists(a) && std::filesystem::exists(b));
    set_age(a, std::chrono::seconds(300));
    set_age(b, std::chrono::seconds(200));

    // Room for a and b: c (a coarser grid, a smaller file) takes b's place, b being the least
    // recently used once a is read again.
    const std::uintmax_t b_size = std::filesystem::file_size(b);
    const std::uintmax_t limit = std::filesystem::file_size(a) + b_size;
    qputenv("GARMENT_CACHE_LIMIT", QByteArray::number(static_cast<qulonglong>(limit)));
    QVERIFY(field_at(0.020).from_cache);
    const SignedDistanceField c = field_at(0.022);
    QVERIFY(!c.from_cache);
    QVERIFY(std::filesystem::file_size(c.cache_file) < b_size);
    QVERIFY2(!std::filesystem::exists(b), "the least recently used file stays");
    QVERIFY(std::filesystem::exists(a));
    QVERIFY(std::filesystem::exists(c.cache_file));

    // A limit smaller than any file: only the file in use stays, and it is read again.
    qputenv("GARMENT_CACHE_LIMIT", "1");
    const SignedDistanceField d = field_at(0.023);
    QVERIFY(!d.from_cache);
    QVERIFY(std::filesystem::exists(d.cache_file));
    QVERIFY(!std::filesystem::exists(a));
    QVERIFY(!std::filesystem::exists(c.cache_file));
    const SignedDistanceField d_again = field_at(0.023);
    qunsetenv("GARMENT_CACHE_LIMIT");
    QVERIFY(d_again.from_cache);
    QVERIFY(same_field(d_again.grid, d.grid));
    QVERIFY(std::filesystem::exists(d.cache_file));
  }

  // (d) A run killed while writing leaves its temporary (`<file>.tmp-<pid>-<hex>`, up to the
  // whole file's size): removed once its process is gone, kept while its process may still be
  // writing it. A partial file under the final name is never taken for a complete one.
  void stale_temporaries_are_removed_and_partial_files_never_used() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    SignedDistanceOptions options;
    options.spacing = 0.02;
    options.cache_directory = folder.path().toStdString();
    const BodyMesh body = two_boxes();
    const DistanceGrid fresh = compute_signed_distance_grid(body, options.spacing, options.margin);
    const std::filesystem::path file = signed_distance_field(body, options).cache_file;
    const std::string good = file_bytes(file);
    const std::string half = good.substr(0, good.size() / 2);

    auto temporary = [&](pid_t pid, const char* suffix) {
      std::filesystem::path path = file;
      path += ".tmp-" + std::to_string(pid) + "-" + suffix;
      return path;
    };
    const std::filesystem::path dead = temporary(dead_process_id(), "1f2e3d4c");
    const std::filesystem::path live = temporary(getpid(), "5a6b7c8d");
    // Untouched for two hours: whatever its process id names now, no write takes that long.
    const std::filesystem::path abandoned = temporary(getpid(), "9e8d7c6b");
    write_bytes(dead, half);
    write_bytes(live, half);
    write_bytes(abandoned, half);
    set_age(abandoned, std::chrono::hours(2));

    // Partial files under the final name, as a copy cut short would leave: every cut is refused.
    for (const std::size_t length : {std::size_t{100}, half.size(), good.size() - 1}) {
      write_bytes(file, good.substr(0, length));
      const SignedDistanceField after = signed_distance_field(body, options);
      QVERIFY2(!after.from_cache, qPrintable(QString("cut at %1 bytes").arg(length)));
      QVERIFY(same_field(after.grid, fresh));
      QVERIFY(file_bytes(file) == good);
    }
    write_bytes(file, good + "x");
    QVERIFY(!signed_distance_field(body, options).from_cache);

    QVERIFY2(!std::filesystem::exists(dead), "the temporary of a process gone stays");
    QVERIFY2(std::filesystem::exists(live), "the temporary of a live process was removed");
    QVERIFY2(!std::filesystem::exists(abandoned), "a temporary untouched for 2 hours stays");
    QVERIFY(signed_distance_field(body, options).from_cache);
    QVERIFY(std::filesystem::exists(live));
  }

  // The limit's default and its variable.
  void limit_reads_the_environment() {
    qunsetenv("GARMENT_CACHE_LIMIT");
    QCOMPARE(distance_grid_cache_limit(), std::uint64_t{2} << 30);
    const std::pair<const char*, std::uint64_t> cases[] = {
        {"123456", 123456},
        {"0", 0},
        {"500M", std::uint64_t{500} << 20},
        {"4G", std::uint64_t{4} << 30},
        {"64k", std::uint64_t{64} << 10},
        {"99999999999G", std::numeric_limits<std::uint64_t>::max()},  // past 2^64: no limit
        {"lots", std::uint64_t{2} << 30},                             // unreadable: the default
        {"-5", std::uint64_t{2} << 30},
        {"5 G", std::uint64_t{2} << 30},
        {"5T", std::uint64_t{2} << 30},
    };
    for (const auto& [text, expected] : cases) {
      qputenv("GARMENT_CACHE_LIMIT", text);
      QCOMPARE(distance_grid_cache_limit(), expected);
    }
    qunsetenv("GARMENT_CACHE_LIMIT");
  }

  // The checksum is XXH64: the published values of xxHash's reference implementation, and the
  // same value whatever pieces the bytes come in.
  void checksum_is_xxh64() {
    const std::pair<std::string, std::uint64_t> published[] = {
        {"", 0xEF46DB3751D8E999ull},
        {"a", 0xD24EC4F1A98C6E5Bull},
        {"abc", 0x44BC2CF5AD770999ull},
        {"Nobody inspects the spammish repetition", 0xFBCEA83C8A378BF1ull},
    };
    for (const auto& [text, expected] : published)
      QCOMPARE(hash64(text.data(), text.size()), expected);
    std::string bytes(1000, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i)
      bytes[i] = static_cast<char>(i * 131 + 7);
    const std::uint64_t whole = hash64(bytes.data(), bytes.size(), 42);
    for (const std::size_t piece : {1, 7, 31, 32, 33, 100}) {
      Hash64 streamed(42);
      for (std::size_t at = 0; at < bytes.size(); at += piece)
        streamed.update(bytes.data() + at, std::min(piece, bytes.size() - at));
      QCOMPARE(streamed.digest(), whole);
    }
    QVERIFY(hash64(bytes.data(), bytes.size(), 43) != whole);
  }
};

QTEST_GUILESS_MAIN(DistanceCacheTest)
#include "test_distance_cache.moc"
