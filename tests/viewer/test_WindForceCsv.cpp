// --wind-force's CSV: a row per wind sample of each engine, named by its DEF name, the force's
// norm beside its components; written whole or not at all.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/FallingSquare.h"
#include "support/TempDir.h"
#include "viewer/WindForceCsv.h"

using namespace figment;

namespace {

std::vector<std::string> lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(WindForceCsv, ARowPerSampleWithTheForcesNorm) {
  const test::FallingSquare square(0.1, "windDirection 0 1 0 windAmplitude 0.5 windFrequency 2");
  ASSERT_TRUE(square.read());
  const session::DrapeRecorder recorder(square.context(), {}, 0.01);
  square.drape();
  const std::vector<session::WindSample>& samples = recorder.windSamples(square.engine());
  ASSERT_FALSE(samples.empty());
  const test::TempDir dir;
  const std::string path = (dir.path() / "wind.csv").string();
  ASSERT_EQ(viewer::writeWindForceCsv(path, {&square.engine()}, recorder), "");
  const std::vector<std::string> rows = lines(path);
  ASSERT_EQ(rows.size(), samples.size() + 1);
  EXPECT_EQ(rows[0], "engine,time_s,pressure_Pa,phase_rad,force_x_N,force_y_N,force_z_N,force_N");
  std::istringstream last(rows.back());
  std::vector<std::string> cells;
  for (std::string cell; std::getline(last, cell, ',');) cells.push_back(cell);
  ASSERT_EQ(cells.size(), 8u);
  EXPECT_EQ(cells[0], "Drape");
  const double fx = std::stod(cells[4]), fy = std::stod(cells[5]), fz = std::stod(cells[6]);
  EXPECT_NEAR(std::stod(cells[7]), std::sqrt(fx * fx + fy * fy + fz * fz), 1e-6 * (1 + std::abs(fy)));
  EXPECT_NEAR(std::stod(cells[1]), samples.back().time, 1e-9);
}

TEST(WindForceCsv, AnUnwritablePathIsAnErrorAndNoFile) {
  const test::FallingSquare square(0.01);
  ASSERT_TRUE(square.read());
  const session::DrapeRecorder recorder(square.context(), {}, 0.0);
  const test::TempDir dir;
  dir.file("blocker", "a file where the folder would be\n");
  const std::string path = (dir.path() / "blocker" / "wind.csv").string();  // its folder is a file
  EXPECT_NE(viewer::writeWindForceCsv(path, {&square.engine()}, recorder), "");
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
