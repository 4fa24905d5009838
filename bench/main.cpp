// figment-bench: one subcommand per study; each writes CSV into --out.
#include "DrapeStudy.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"FIGMENT benchmarks: studies that write CSV"};
  app.require_subcommand(1);

  figment::bench::DrapeStudyOptions drape;
  CLI::App* drapeCommand = app.add_subcommand("drape", "time the drape of every garment in a scene");
  drapeCommand->add_option("--scene", drape.scene, "scene to drape")->capture_default_str()->check(CLI::ExistingFile);
  drapeCommand->add_option("--repeat", drape.repeat, "runs per garment")->capture_default_str()->check(CLI::PositiveNumber);
  drapeCommand->add_option("--out", drape.outDir, "folder for drape.csv")->capture_default_str();

  CLI11_PARSE(app, argc, argv);
  if (drapeCommand->parsed()) return figment::bench::runDrapeStudy(drape);
  return 1;
}
