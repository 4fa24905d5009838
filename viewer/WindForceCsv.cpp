#include "viewer/WindForceCsv.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "io/AtomicFile.h"

namespace figment::viewer {

std::string writeWindForceCsv(const std::string& path, const std::vector<ClothEngine*>& engines,
                              const session::DrapeRecorder& recorder) {
  return writeAtomically(path, [&](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out.precision(9);
    out << "engine,time_s,pressure_Pa,phase_rad,force_x_N,force_y_N,force_z_N,force_N\n";
    for (const ClothEngine* engine : engines)
      for (const session::WindSample& s : recorder.windSamples(*engine))
        out << engine->getName().getString() << ',' << s.time << ',' << s.pressure << ',' << s.phase << ','
            << s.force.x() << ',' << s.force.y() << ',' << s.force.z() << ',' << s.force.norm() << '\n';
    out.close();
    return out ? "" : std::string("cannot write the wind force: ") + std::strerror(errno);
  });
}

}  // namespace figment::viewer
