#include "io/ProgressiveScript.h"

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/AtomicFile.h"
#include "io/Fnv1a.h"

namespace figment {

namespace {
constexpr const char* kMagic = "figment-progressive-mesh";
constexpr int kVersion = 1;

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

void writeVec(std::ostream& out, const Vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, " %.17g %.17g %.17g", v.x(), v.y(), v.z());
  out << text;
}

void writeSplit(std::ostream& out, const VertexSplit& s) {
  out << "split " << s.kept << ' ' << s.added;
  writeVec(out, s.keptRest);
  writeVec(out, s.addedRest);
  writeVec(out, s.collapsedRest);
  out << ' ' << s.restored.size();
  for (const RestoredFace& f : s.restored)
    out << ' ' << f.face << ' ' << f.corners[0] << ' ' << f.corners[1] << ' ' << f.corners[2];
  out << ' ' << s.repointed.size();
  for (int f : s.repointed) out << ' ' << f;
  out << '\n';
}

// Reads one split line; throws a reason (without the path) when it is malformed or
// names a vertex or face the garment does not have.
VertexSplit parseSplit(const std::string& line, int vertices, int faces) {
  std::istringstream in(line);
  std::string word;
  VertexSplit s;
  auto vec = [&](Vec3& v) { in >> v.x() >> v.y() >> v.z(); };
  in >> word >> s.kept >> s.added;
  vec(s.keptRest), vec(s.addedRest), vec(s.collapsedRest);
  size_t count = 0;
  in >> count;
  if (!in || word != "split" || count > 2) throw std::runtime_error("not a split");
  s.restored.resize(count);
  for (RestoredFace& f : s.restored) in >> f.face >> f.corners[0] >> f.corners[1] >> f.corners[2];
  in >> count;
  if (!in || count > static_cast<size_t>(faces)) throw std::runtime_error("not a split");
  s.repointed.resize(count);
  for (int& f : s.repointed) in >> f;
  if (!in || (in >> word)) throw std::runtime_error("not a split");
  auto vertex = [&](int v) { return v >= 0 && v < vertices; };
  auto face = [&](int f) { return f >= 0 && f < faces; };
  bool valid = vertex(s.kept) && vertex(s.added) && s.kept != s.added;
  for (const RestoredFace& f : s.restored)
    valid = valid && face(f.face) && vertex(f.corners[0]) && vertex(f.corners[1]) && vertex(f.corners[2]);
  for (int f : s.repointed) valid = valid && face(f);
  if (!valid) throw std::runtime_error("a vertex or face out of range");
  return s;
}
}  // namespace

std::uint64_t garmentHash(const TriangleMesh& garment) {
  Fnv1a hash;
  hash.add(static_cast<std::uint64_t>(garment.vertices.size()));
  for (const Vec3& v : garment.vertices)
    for (int axis = 0; axis < 3; ++axis) hash.add(static_cast<float>(v[axis]));
  hash.add(static_cast<std::uint64_t>(garment.triangles.size()));
  for (const Triangle& t : garment.triangles)
    for (int c : t) hash.add(static_cast<std::int32_t>(c));
  return hash.value();
}

void writeProgressiveScript(const ProgressiveMesh& mesh, const std::string& path) {
  const std::string error = writeAtomically(path, [&](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out << kMagic << ' ' << kVersion << '\n';
    out << "garment " << mesh.full.vertices.size() << ' ' << mesh.full.triangles.size() << ' '
        << hex(garmentHash(mesh.full)) << '\n';
    out << "splits " << mesh.splits.size() << '\n';
    for (const VertexSplit& split : mesh.splits) writeSplit(out, split);
    out.flush();
    return out ? "" : "cannot write";
  });
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
}

ProgressiveMesh readProgressiveScript(const std::string& path, const TriangleMesh& garment) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  auto fail = [&](int line, const std::string& reason) {
    return std::runtime_error(path + ":" + std::to_string(line) + ": " + reason);
  };
  std::string magic, word, hash;
  int version = 0;
  size_t vertices = 0, faces = 0, splits = 0;
  if (!(in >> magic >> version) || magic != kMagic || version != kVersion)
    throw fail(1, std::string("not a ") + kMagic + " " + std::to_string(kVersion) + " file");
  if (!(in >> word >> vertices >> faces >> hash) || word != "garment")
    throw fail(2, "expected garment VERTICES FACES HASH");
  if (vertices != garment.vertices.size() || faces != garment.triangles.size())
    throw fail(2, "for a garment of " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
                      " faces, not this one's " + std::to_string(garment.vertices.size()) + " and " +
                      std::to_string(garment.triangles.size()));
  if (hash != hex(garmentHash(garment)))
    throw fail(2, "for another garment (hash " + hash + ", this one's " + hex(garmentHash(garment)) + ")");
  if (!(in >> word >> splits) || word != "splits" || splits > vertices) throw fail(3, "expected splits COUNT");
  ProgressiveMesh mesh{garment, {}};
  std::string line;
  std::getline(in, line);
  for (size_t k = 0; k < splits; ++k) {
    const int number = static_cast<int>(k) + 4;
    if (!std::getline(in, line))
      throw fail(number, "the file ends after " + std::to_string(k) + " of " + std::to_string(splits) + " splits");
    try {
      mesh.splits.push_back(parseSplit(line, static_cast<int>(vertices), static_cast<int>(faces)));
    } catch (const std::runtime_error& error) {
      throw fail(number, error.what());
    }
  }
  return mesh;
}

}  // namespace figment
