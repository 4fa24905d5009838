#pragma once
// What every tool's main does around its own work: parse the command line, find the
// body on the model search path, bring it into the scene frame (metres, y up) the way a
// MeshFile with the same fields would, check it stands upright at a human size, and turn
// any error into one line "<program>: <file>: <reason>" on stderr with exit status 1.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "io/UpAxis.h"
#include "sim/core/TriangleMesh.h"

namespace figment::tools {

// The body a tool works on, as its command line names it: the MeshFile fields fileName,
// collisionExclude, metresPerUnit and upAxis.
struct BodyInput {
  std::string name = "human.zae";
  std::vector<std::string> exclude = {"eyes"};
  double metresPerUnit = 1.0;
  UpAxis upAxis = UpAxis::Y;
};

// Adds --body, --exclude, --metres-per-unit and --up-axis to `app`, read into `body`.
void addBodyOptions(CLI::App& app, BodyInput& body);

class ToolMain {
 public:
  explicit ToolMain(std::string program) : program_(std::move(program)) {}

  const std::string& program() const { return program_; }

  // Prints "<program>: <message>" to stderr; returns exit status 1.
  int fail(const std::string& message) const;

  // Parses the command line into `app`'s options: -1 to go on, else the exit status
  // (0 after --help, 1 after a bad option).
  int parse(CLI::App& app, int argc, char** argv) const;

  // Finds the body file on the model search path, reads it (metresPerUnit, upAxis,
  // without the meshes named in `exclude`), checks it (bodyFrameProblem) and returns the
  // exit status of `work` on it. A body not found, a body that fails the check, or an
  // exception, is one line and status 1: the importer's and exporter's messages start
  // with their path; others get the body's.
  int withBody(const BodyInput& input,
               const std::function<int(const TriangleMesh& body, const std::string& bodyPath)>& work) const;

 private:
  std::string program_;
};

// Why `body` (as read with `input`'s metresPerUnit and upAxis) cannot be fitted or
// dressed, with the options that would bring it upright and to a human stature; "" when
// it stands along +y and is kMinStature to kMaxStature (sim/body/BodyStance.h) tall.
std::string bodyFrameProblem(const TriangleMesh& body, const BodyInput& input);

}  // namespace figment::tools
