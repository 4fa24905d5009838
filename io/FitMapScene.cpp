#include "io/FitMapScene.h"

#include <fstream>
#include <stdexcept>

#include "io/AtomicFile.h"
#include "sim/fit/FitMap.h"

namespace figment {

namespace {

void writeGarment(std::ostream& out, const TriangleMesh& garment, const std::vector<int>& bands) {
  out << "  Separator {\n    ShapeHints { vertexOrdering COUNTERCLOCKWISE  shapeType UNKNOWN_SHAPE_TYPE  creaseAngle "
         "1.0 }\n    Material { diffuseColor [";
  for (int band = 0; band < kFitMapBands; ++band) {
    const Vec3 c = fitMapColour(band);
    out << (band ? ", " : " ") << c.x() << ' ' << c.y() << ' ' << c.z();
  }
  out << " ] }\n    MaterialBinding { value PER_VERTEX_INDEXED }\n    Coordinate3 { point [\n";
  for (const Vec3& p : garment.vertices) out << "      " << p.x() << ' ' << p.y() << ' ' << p.z() << ",\n";
  out << "    ] }\n    IndexedFaceSet {\n      coordIndex [\n";
  for (const Triangle& t : garment.triangles) out << "        " << t[0] << ", " << t[1] << ", " << t[2] << ", -1,\n";
  out << "      ]\n      materialIndex [\n";
  for (const Triangle& t : garment.triangles)
    out << "        " << bands[t[0]] << ", " << bands[t[1]] << ", " << bands[t[2]] << ", -1,\n";
  out << "      ]\n    }\n  }\n";
}

}  // namespace

void writeFitMapScene(const std::string& path, const TriangleMesh& garment, const std::vector<int>& bands,
                      const std::string& bodyFile) {
  if (bands.size() != garment.vertices.size()) throw std::runtime_error(path + ": a band for every vertex is needed");
  const std::string error = writeAtomically(path, [&](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out.precision(7);
    out << "#Inventor V2.1 ascii\n\n# A fit map (figment-size --fit-map): blue at rest to red at the fabric's "
           "limit, eight bands.\n\nSeparator {\n  DirectionalLight { direction -0.4 -0.5 -1 intensity 0.75 }\n"
           "  DirectionalLight { direction 0.6 -0.3 0.8 intensity 0.5 }\n  Separator {\n"
           "    Material { diffuseColor 0.80 0.58 0.45  specularColor 0.1 0.1 0.1  shininess 0.2 }\n"
           "    ShapeHints { vertexOrdering COUNTERCLOCKWISE  shapeType SOLID  creaseAngle 1.0 }\n"
           "    MeshFile { fileName \""
        << bodyFile << "\" }\n  }\n";
    writeGarment(out, garment, bands);
    out << "}\n";
    out.close();
    return out ? "" : "cannot be written";
  });
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
}

}  // namespace figment
