// figment-bench: one subcommand per study; each writes CSV into --out.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "BodyStudy.h"
#include "CollisionStudy.h"
#include "CsvFile.h"
#include "DrapeStudy.h"
#include "FitStudy.h"
#include "MethodStudy.h"
#include "ProgressiveStudy.h"
#include "RenderStudy.h"
#include "SizeStudy.h"
#include "StabilityStudy.h"
#include "TradeoffStudy.h"
#include "headless/InitHeadless.h"

namespace {

using namespace figment::bench;

// The options several studies share, each the same way: a scene (or scenes) that must exist,
// the output folder, and a repeat count that must be positive.
template <typename Target>
void addSceneOption(CLI::App* command, Target& scenes, const std::string& description) {
  command->add_option("--scene", scenes, description)->capture_default_str()->check(CLI::ExistingFile);
}

void addOutOption(CLI::App* command, std::string& outDir, const std::string& files) {
  command->add_option("--out", outDir, "folder for " + files)->capture_default_str();
}

void addRepeatOption(CLI::App* command, int& repeat, const std::string& description) {
  command->add_option("--repeat", repeat, description)->capture_default_str()->check(CLI::PositiveNumber);
}

// The progressive and size studies' time steps: the method's times each factor.
void addStepFactorOption(CLI::App* command, std::vector<double>& factors) {
  command
      ->add_option("--step-factor", factors, "drape at the method's time step times each (repeat; medians over them)")
      ->capture_default_str()
      ->check(CLI::Range(0.5, 2.0));
}

CLI::App* addDrapeCommand(CLI::App& app, DrapeStudyOptions& drape) {
  CLI::App* drapeCommand = app.add_subcommand("drape", "time the drape of every garment in a scene");
  addSceneOption(drapeCommand, drape.scene, "scene to drape");
  addRepeatOption(drapeCommand, drape.repeat, "runs per garment");
  addOutOption(drapeCommand, drape.outDir, "drape.csv");
  drapeCommand
      ->add_option("--body", drape.bodies,
                   "what the garments collide with, each timed: scene, exact (the Mannequin's body "
                   "triangles) or a volumes .iv file")
      ->capture_default_str();
  drapeCommand
      ->add_option("--broad-phase", drape.broadPhase,
                   "on, off, or both in turn (repeat the option): body parts far from the garment "
                   "tested or not (the drape is the same)")
      ->capture_default_str()
      ->check(CLI::IsMember({"on", "off"}));
  drapeCommand->add_option("--integrator", drape.integrator, "every engine's integrator instead of the scene's")
      ->check(CLI::IsMember({"EULER", "SYMPLECTIC", "HEUN", "IMPLICIT"}));
  drapeCommand->add_option("--time-step", drape.timeStep, "every engine's time step instead of the scene's, s")
      ->check(CLI::PositiveNumber);
  drapeCommand->add_option("--positions", drape.positionsFile, "CSV of the last drape's node positions");
  return drapeCommand;
}

CLI::App* addStabilityCommand(CLI::App& app, StabilityStudyOptions& stability) {
  CLI::App* stabilityCommand = app.add_subcommand(
      "stability", "integrators x strain clamping x limiters over time steps: stability and accuracy");
  addSceneOption(stabilityCommand, stability.scene, "scene to drape");
  addOutOption(stabilityCommand, stability.outDir, "stability.csv and stability.png");
  stabilityCommand->add_flag("--quick", stability.quick, "a few configurations and steps, 0.3 s runs (under a minute)");
  stabilityCommand->add_option("--dt", stability.timeSteps, "time steps to sweep, s (the smallest is the reference)")
      ->check(CLI::PositiveNumber);
  stabilityCommand->add_option("--integrator", stability.integrators, "only these integrators (repeat the option)")
      ->check(CLI::IsMember({"euler", "symplectic", "heun"}));
  stabilityCommand->add_option("--strain-limit", stability.strainLimit, "strain clamping range")->capture_default_str();
  stabilityCommand->add_option("--acceleration-limit", stability.accelerationLimit, "limiter cap, multiples of g")
      ->capture_default_str();
  return stabilityCommand;
}

CLI::App* addRenderCommand(CLI::App& app, RenderStudyOptions& render) {
  CLI::App* renderCommand =
      app.add_subcommand("render", "render time with the hybrid nodes and with plain depth buffering");
  addSceneOption(renderCommand, render.scenes, "scenes to render (repeat the option)");
  renderCommand->add_option("--width", render.width, "image width")->capture_default_str()->check(CLI::Range(1, 8192));
  renderCommand->add_option("--height", render.height, "image height")
      ->capture_default_str()
      ->check(CLI::Range(1, 8192));
  addRepeatOption(renderCommand, render.repeat, "renders per scene and mode");
  addOutOption(renderCommand, render.outDir, "render.csv");
  return renderCommand;
}

CLI::App* addCollisionCommand(CLI::App& app, CollisionStudyOptions& collision) {
  CLI::App* collisionCommand = app.add_subcommand(
      "collision", "per body part: capsule and radial depth volumes against the body (gap, enclosure, query cost)");
  collisionCommand->add_option("--body", collision.body, "body mesh (model search path)")->capture_default_str();
  collisionCommand->add_option("--harmonics", collision.harmonics, "Fourier terms K of the radial depth volumes")
      ->capture_default_str()
      ->check(CLI::Range(0, 31));  // 64 angular samples per section
  collisionCommand->add_option("--section-spacing", collision.sectionSpacing, "m between radial depth sections")
      ->capture_default_str()
      ->check(CLI::Range(0.002, 0.2));
  addOutOption(collisionCommand, collision.outDir, "collision.csv and collision.png");
  return collisionCommand;
}

CLI::App* addMethodCommand(CLI::App& app, MethodStudyOptions& methods) {
  CLI::App* command = app.add_subcommand(
      "methods", "a garment by each method and time step: steps, wall to rest, deviation, strain, nodes inside");
  addSceneOption(command, methods.scenes,
                 "scenes whose last garment (an outfit's outer layer) is draped (repeat the option)");
  command
      ->add_option(
          "--method", methods.methods,
          "INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G], e.g. heun:1.5e-4:clamp:30, implicit+penalty:0.05 (repeat)")
      ->capture_default_str();
  command->add_option("--reference", methods.reference, "the converged run deviations are measured against")
      ->capture_default_str();
  addRepeatOption(command, methods.repeat, "runs per method (median wall time)");
  addOutOption(command, methods.outDir, "methods.csv");
  return command;
}

CLI::App* addProgressiveCommand(CLI::App& app, ProgressiveStudyOptions& progressive) {
  CLI::App* command = app.add_subcommand(
      "progressive", "a garment draped progressively against the full garment: wall to rest, speed-up, deviation");
  addSceneOption(command, progressive.scene, "scene whose last garment is draped progressively");
  command->add_option("--method", progressive.methods, "INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G] (repeat)")
      ->capture_default_str();
  command
      ->add_option("--schedule", progressive.schedules,
                   "BEGIN_SHARE:RATE: begin level as a share of the levels, splits per simulated second "
                   "(0: all once the begin level rests) (repeat)")
      ->capture_default_str();
  addStepFactorOption(command, progressive.stepFactors);
  command
      ->add_option("--coarse-share", progressive.coarseShare,
                   "a scene with no progressiveScript: its garment decimated to this share of its sections")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1.0));
  addOutOption(command, progressive.outDir, "progressive.csv");
  return command;
}

CLI::App* addSizeCommand(CLI::App& app, SizeStudyOptions& sizes) {
  CLI::App* command = app.add_subcommand(
      "sizes", "a garment resampled to each size, draped whole and progressively: wall to rest, speed-up, deviation");
  addSceneOption(command, sizes.scene, "scene whose last garment is resampled");
  command->add_option("--sections", sizes.sizes, "garment sizes, triangles (repeat)")
      ->capture_default_str()
      ->check(CLI::Range(8, 1000000));
  command->add_option("--method", sizes.method, "INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G]")->capture_default_str();
  command->add_option("--coarse-share", sizes.coarseShare, "the progressive drape's first level, share of the sections")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1.0));
  command->add_option("--split-time", sizes.splitTime, "simulated s over which every split is made")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command->add_option("--max-time", sizes.maxTime, "simulated s a drape may take before it counts as never resting")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  addStepFactorOption(command, sizes.stepFactors);
  addOutOption(command, sizes.outDir, "sizes.csv");
  return command;
}

CLI::App* addTradeoffCommand(CLI::App& app, TradeoffStudyOptions& tradeoff) {
  CLI::App* command = app.add_subcommand(
      "tradeoff", "every method choice against a converged reference: wall to rest against deviation, Pareto front");
  addSceneOption(command, tradeoff.scenes, "scenes whose last garment (an outfit's outer layer) is draped (repeat)");
  command->add_option("--method", tradeoff.methods, "INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G] (repeat)")
      ->capture_default_str();
  command
      ->add_option("--body", tradeoff.bodies,
                   "volumes, capsules, triangles or mix (the volumes, triangles where the garment starts) (repeat)")
      ->capture_default_str()
      ->check(CLI::IsMember({"volumes", "capsules", "triangles", "mix"}));
  command->add_option("--schedule", tradeoff.schedules, "off or BEGIN_SHARE:RATE, progressive (repeat)")
      ->capture_default_str();
  command->add_option("--resolution", tradeoff.resolutions, "the garment's sections times each (repeat)")
      ->capture_default_str()
      ->check(CLI::Range(0.05, 20.0));
  command->add_option("--reference", tradeoff.reference, "the converged drape, on the body's triangles")
      ->capture_default_str();
  command->add_flag("!--no-reference-check", tradeoff.checkReference, "skip the reference's half-step drape");
  addRepeatOption(command, tradeoff.repeat, "drapes per configuration (median wall)");
  command->add_flag("--quick", tradeoff.quick,
                    "the dress, 4 methods x 3 bodies x 2 schedules x 2 resolutions, once (under 5 minutes)");
  addOutOption(command, tradeoff.outDir, "tradeoff.csv, tradeoff-reference.csv, tradeoff.png");
  return command;
}

CLI::App* addBodyCommand(CLI::App& app, BodyStudyOptions& bodies) {
  CLI::App* command = app.add_subcommand(
      "bodies", "make and measure MakeHuman bodies to the 60 measurement sets: median, p90, skin crossings");
  addRepeatOption(command, bodies.repeat, "timings per body (median)");
  addOutOption(command, bodies.outDir, "bodies.csv");
  return command;
}

CLI::App* addFitCommand(CLI::App& app, FitStudyOptions& fit) {
  CLI::App* command = app.add_subcommand(
      "recommend", "size recommendation over the chart's bodies: own size, time, steps saved by warm starts");
  command->add_option("--style", fit.styles, "styles (repeat the option)")->capture_default_str();
  command->add_option("--sex", fit.sexes, "female, male (repeat the option)")
      ->capture_default_str()
      ->check(CLI::IsMember({"female", "male"}));
  addRepeatOption(command, fit.repeat, "warm recommendations timed per body (median)");
  command->add_option("--grid", fit.grid, "bodies along the chart per style and sex: the monotony check")
      ->capture_default_str();
  command->add_option("--grid-beyond", fit.gridBeyond, "sizes the grid reaches beyond each end of the chart")
      ->capture_default_str();
  addOutOption(command, fit.outDir, "fit.csv and fit-grid.csv");
  return command;
}

}  // namespace

int main(int argc, char** argv) {
  // Off-screen Coin (the render study), its messages as one-line warnings (a ClothEngine's
  // error is reported by the study) and the node kit
  figment::initHeadless("figment-bench: warning: ");
  CLI::App app{"FIGMENT benchmarks: studies that write CSV"};
  app.require_subcommand(1);
  DrapeStudyOptions drape;
  StabilityStudyOptions stability;
  stability.plotScript = FIGMENT_PLOT_STABILITY;
  RenderStudyOptions render;
  CollisionStudyOptions collision;
  collision.plotScript = FIGMENT_PLOT_COLLISION;
  MethodStudyOptions methods;
  ProgressiveStudyOptions progressive;
  progressive.plotScript = FIGMENT_PLOT_PROGRESSIVE;
  SizeStudyOptions sizes;
  sizes.plotScript = FIGMENT_PLOT_SIZES;
  TradeoffStudyOptions tradeoff;
  tradeoff.plotScript = FIGMENT_PLOT_TRADEOFF;
  BodyStudyOptions bodies;
  FitStudyOptions fit;
  // Each subcommand, in the order --help lists them, with the study it runs.
  const std::pair<CLI::App*, std::function<int()>> studies[] = {
      {addDrapeCommand(app, drape), [&] { return runDrapeStudy(drape); }},
      {addStabilityCommand(app, stability), [&] { return runStabilityStudy(stability); }},
      {addRenderCommand(app, render), [&] { return runRenderStudy(render); }},
      {addCollisionCommand(app, collision), [&] { return runCollisionStudy(collision); }},
      {addMethodCommand(app, methods), [&] { return runMethodStudy(methods); }},
      {addProgressiveCommand(app, progressive), [&] { return runProgressiveStudy(progressive); }},
      {addSizeCommand(app, sizes), [&] { return runSizeStudy(sizes); }},
      {addTradeoffCommand(app, tradeoff),
       [&] { return runTradeoffStudy(tradeoff.quick ? quickTradeoff(tradeoff) : tradeoff); }},
      {addBodyCommand(app, bodies), [&] { return runBodyStudy(bodies); }},
      {addFitCommand(app, fit), [&] { return runFitStudy(fit); }},
  };

  CLI11_PARSE(app, argc, argv);
  for (const auto& [command, run] : studies)
    if (command->parsed()) {
      // Every study writes into --out: a file there, or a folder that cannot be made, is
      // refused before the study's minutes or hours, not thrown at its end.
      if (const std::string error = makeOutFolder(command->get_option("--out")->as<std::string>()); !error.empty()) {
        std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
        return 1;
      }
      return run();
    }
  return 1;
}
