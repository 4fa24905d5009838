#pragma once
// What figment-precompute puts on the work queue (serve/workers/JobQueue.h): render requests in
// their canonical text, either one per line of a file (query strings as GET /api/render
// takes them) or the catalogue's grid: every style in every size it is sold in, in its
// default colour, on the made body of each sex and measurements, pose and view asked for.
// Each request is checked as the server checks one, against the same garment catalogue; a
// bad one stops the whole plan with one line naming it (nothing is queued).

#include <string>
#include <variant>
#include <vector>

namespace figment {
class GarmentCatalogue;
}

namespace figment::serve {

class PrecomputePlan {
 public:
  using Requests = std::vector<std::string>;  // canonical texts, each once, in the order met

  // One request per line of `text` read from `fileName`; blank lines and lines starting
  // with # are skipped. Or "FILE:LINE: what is wrong".
  // `catalogue` as the server's (null: the Mannequin's requests alone).
  static std::variant<Requests, std::string> fromLines(const std::string& text, const std::string& fileName,
                                                       const GarmentCatalogue* catalogue);

  struct Grid {
    std::vector<std::string> sexes;   // female, male; none: every sex the catalogue sells to
    std::vector<std::string> bodies;  // "STATURE,BUST,WAIST,HIPS" in metres; none: each sex's default body
    std::vector<std::string> poses;   // a made body's (MeasuredPoses); none: rest
    std::vector<std::string> views;   // as the view parameter takes them; none: front
    std::string size = "800x600";     // WxH
  };
  // For each sex: every style sold to it × each size it is sold in, in its default colour,
  // × bodies × poses × views (a sewn style at rest only: it is sewn standing).
  static std::variant<Requests, std::string> fromCatalogue(const Grid& grid, const GarmentCatalogue& catalogue);
};

}  // namespace figment::serve
