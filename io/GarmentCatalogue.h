#pragma once
// The garment catalogue's files (scenes/catalogue/index.txt and one file per style): the
// styles a shop sells, each in the chart's sizes per sex and in its colours, so a scene,
// the tools and the service name one garment as "style:size[:rrggbb]" ("dress:M",
// "pencil:38", "tshirt:XL:222222"). A size is the chart's letter code, in the sex the
// style's file lists first, or its number (unique over both sexes: "tshirt:38" is the
// women's M). The garment itself is the style cut around the size's chart body
// (sim/garment/GarmentStyle.h, sim/garment/SizeChart.h), or, for a pattern style, that
// size's sewing pattern from a graded pattern index (io/PatternIndexFile.h: a shop's own
// garments, scenes/patterns/), sewn on the body and draped. Format: docs/sizes.md.

#include <string>
#include <vector>

#include "io/PatternIndexFile.h"
#include "sim/fit/SizeFitter.h"
#include "sim/garment/GarmentStyle.h"
#include "sim/garment/SizeChart.h"

namespace figment {

struct CatalogueStyle {
  std::string name;                       // a sim/garment style ("dress"), or a pattern style's own ("tee")
  std::vector<Sex> sexes;                 // in the file's order: the first is the one a letter code names
  std::vector<std::string> female, male;  // the chart's sizes it is cut in (letter codes), smallest first
  std::vector<std::string> colours;       // rrggbb, lower case; the first is the default
  const std::vector<std::string>& sizes(Sex sex) const { return sex == Sex::Female ? female : male; }
  std::string fabric;                // a material preset (sim/cloth/MaterialPresets.h)
  std::vector<std::string> regions;  // the body regions its fit is told for (sim/fit/FitRegion.h)
  // A pattern style's: the pattern index's style it is sewn from ("tshirt"), and the
  // index's entry of each size it is sold in; "" and empty for a generator's style.
  std::string pattern;
  std::vector<PatternIndexEntry> patterns;
  // One line for a shopper: the generator's own, or a pattern style's "about" line.
  std::string about;
  bool sewn() const { return !pattern.empty(); }
  // The pattern of `sex`'s size `size` (letter code), or null.
  const PatternIndexEntry* patternOf(Sex sex, const std::string& size) const;
};

// One garment of the catalogue, resolved from its name.
struct CatalogueItem {
  std::string styleName;                // the catalogue's: "dress", "tee"
  const GarmentStyle* style = nullptr;  // its generator, ease and fabric; null for a pattern style
  // A pattern style's: the size's pattern file (GarmentCode JSON) and the stature of the
  // body it was cut for (m); "" and 0 for a generator's.
  std::string patternFile;
  double madeForStature = 0;
  std::string fabric;                // a material preset: the generator's, or the pattern style's file's
  std::vector<std::string> regions;  // as CatalogueStyle::regions
  Sex sex = Sex::Female;
  int size = 0;              // index into the chart's sizes(sex)
  std::string sizeName;      // the letter code: "M"
  std::string colour;        // rrggbb: the name's, else the style's default
  std::string name() const;  // "dress:M:1f40b3"
  bool sewn() const { return !patternFile.empty(); }
};

class GarmentCatalogue {
 public:
  // Reads the index and the files it names (beside it), the chart and the pattern index.
  // Throws std::runtime_error("<file>:<line>: <reason>") for a file that cannot be read, a
  // line it does not understand, a style sim/garment does not have, a pattern style the
  // pattern index does not have (or named as a generator is), a size the chart or the
  // pattern index lacks, a fabric that is not a material preset, a region that is not a
  // body region or a colour that is not six hex digits.
  explicit GarmentCatalogue(const std::string& indexPath);

  const std::vector<CatalogueStyle>& styles() const { return styles_; }
  const SizeChart& chart() const { return chart_; }
  // The pattern index's entries (all of its styles and sizes), or none without one.
  const std::vector<PatternIndexEntry>& patterns() const { return patterns_; }
  const CatalogueStyle* style(const std::string& name) const;

  // "style:size[:rrggbb]" -> the garment. Throws std::invalid_argument naming the value and
  // what is accepted: "dress:Q: no size Q of dress (female XXS, XS, S, M, L, XL)".
  CatalogueItem resolve(const std::string& name) const;
  // As resolve, for a size letter code in `sex`'s sizes (a service's request names the sex).
  CatalogueItem resolve(const std::string& name, Sex sex) const;

  // "dress, skirt, pencil, tshirt": for messages.
  std::string styleNames() const;

 private:
  CatalogueItem resolveIn(const std::string& name, const Sex* sex) const;

  SizeChart chart_;
  std::vector<PatternIndexEntry> patterns_;  // the pattern index's entries: empty without one
  std::vector<CatalogueStyle> styles_;
};

// A pattern style as SizeFitter fits it: its fabric, regions and, for each size it is sold
// in that `chart` has, its pattern read (io/PatternFile.h; throws PatternError for one
// that does not read) with the stature it was cut for.
SewnStyle sewnStyle(const CatalogueStyle& style, const SizeChart& chart);

// The catalogue shipped with the sources (scenes/catalogue/index.txt).
std::string defaultCataloguePath();

}  // namespace figment
