// The distance-field cache under damage (issue 40, item 6): a header altered on disk, a file
// truncated while a run uses it. The fields are compared with a fresh build (never with the
// cache's own reading of itself), on real bodies (tests/data/bodies).

#include <sys/wait.h>
#include <unistd.h>

#include <QTemporaryDir>
#include <QtTest>

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
