#pragma once
// What every tool's main does around its own work: parse the command line, find the
// body on the model search path, and turn any error into one line
// "<program>: <file>: <reason>" on stderr with exit status 1.

#include <CLI/CLI.hpp>

#include "sim/core/TriangleMesh.h"

#include <functional>
#include <string>
#include <vector>

namespace figment::tools {

class ToolMain {
 public:
  explicit ToolMain(std::string program) : program_(std::move(program)) {}

  const std::string& program() const { return program_; }

  // Prints "<program>: <message>" to stderr; returns exit status 1.
  int fail(const std::string& message) const;

  // Parses the command line into `app`'s options: -1 to go on, else the exit status
  // (0 after --help, 1 after a bad option).
  int parse(CLI::App& app, int argc, char** argv) const;

  // Finds the body file `bodyName` on the model search path, reads it (metres, y up,
  // without the meshes named in `exclude`) and returns the exit status of `work` on it.
  // A body not found, or an exception, is one line and status 1: the importer's and
  // exporter's messages start with their path; others get the body's.
  int withBody(const std::string& bodyName, const std::vector<std::string>& exclude,
               const std::function<int(const TriangleMesh& body, const std::string& bodyPath)>& work) const;

 private:
  std::string program_;
};

}  // namespace figment::tools
