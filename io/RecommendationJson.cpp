#include "io/RecommendationJson.h"

#include <cmath>
#include <cstdio>

namespace figment {

namespace {

// A JSON string: the shopper's texts and names are plain, but a quote or control
// character must never break the document.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
      out += escape;
    } else {
      out += c;
    }
  }
  return out + '"';
}

std::string formatted(const char* pattern, double a, double b, double c, double d, double e) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c, d, e);
  return text;
}

double inUnit(double value, double scale) {
  return std::isfinite(value) ? value * scale : -1.0;
}

std::string regionsJson(const SizeFit& fit) {
  std::string out = "{";
  bool first = true;
  for (size_t i = 0; i < fit.regions.size(); ++i) {
    const RegionFit& g = fit.regions[i];
    if (!g.covered()) continue;
    out += (first ? "" : ", ") + quoted(g.name) + ": ";
    out += formatted(
        "{\"stretch_pct\": %.2f, \"max_stretch_pct\": %.2f, \"ease_mm\": %.1f, \"girth_ease_cm\": %.1f, "
        "\"pressure_kpa\": %.3f, ",
        100 * g.meanStrain, 100 * g.maxStrain, 1000 * g.ease, inUnit(g.girthEase, 100), g.pressure / 1000);
    out += "\"verdict\": " + quoted(verdictName(fit.verdicts[i])) + "}";
    first = false;
  }
  return out + "}";
}

}  // namespace

std::string recommendationJson(const Recommendation& r) {
  std::string out = "{";
  if (!r.recommended.empty())
    out += "\"recommended\": " + quoted(r.recommended) + ", \"all_tight\": " + (r.allTight ? "true" : "false") + ", ";
  out += "\"sizes\": {";
  for (size_t s = 0; s < r.sizes.size(); ++s) {
    const SizeFit& fit = r.sizes[s];
    out += (s ? ", " : "") + quoted(fit.size) + ": {\"text\": " + quoted(fit.text) +
           ", \"steps\": " + std::to_string(fit.drape.report.run.iterations) +
           ", \"warm\": " + (fit.drape.report.warm ? "true" : "false") +
           ", \"at_rest\": " + (fit.drape.report.run.atRest ? "true" : "false") + ", \"regions\": " + regionsJson(fit) +
           "}";
  }
  return out + "}}";
}

std::vector<std::string> unrestedSizeLines(const Recommendation& recommendation, const std::string& style,
                                           double maxTime) {
  std::vector<std::string> lines;
  for (const SizeFit& fit : recommendation.sizes)
    if (!fit.drape.report.run.atRest)
      lines.push_back(style + " size " + fit.size + " was not at rest after " + formatted("%g", maxTime, 0, 0, 0, 0) +
                      " s: its fit may still change");
  return lines;
}

}  // namespace figment
