// The size recommendation by simulation (issue 31) on MakeHuman's bodies made to the size
// chart (scenes/sizes/chart.txt): each chart body is recommended its own size of the fitted
// pencil skirt (women) and of the T-shirt (men); the recommendation never gets smaller as a
// body grows along the chart; S on the XL body is tight where it should be and XL on the S
// body loose; figment-size prints the JSON the issue gives and refuses bad input in one line.
// Skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "io/GarmentCatalogue.h"
#include "sim/body/BodyMeasurements.h"
#include "sim/collision/MeshCollider.h"
#include "sim/fit/SizeFitter.h"
#include "support/ChartBodies.h"
#include "support/ProgramRun.h"
#include "support/TempDir.h"

using namespace figment;

namespace {

class SizeRecommendation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    bodies_ = test::loadChartBodies();
    if (bodies_) pencil_ = std::make_unique<SizeFitter>(model(), chart(), *findStyle("pencil"));
  }
  static void TearDownTestSuite() {
    pencil_.reset();
    bodies_.reset();
  }
  void SetUp() override {
    if (!bodies_) GTEST_SKIP() << test::kMakeHumanDataSkip;
  }
  static const HumanModel& model() { return bodies_->human->model(); }
  static const SizeChart& chart() { return bodies_->chart; }
  static int index(Sex sex, const std::string& name) { return chart().find(sex, name); }
  static const Verdict* verdictAt(const SizeFit& fit, const std::string& region) {
    for (size_t r = 0; r < fit.regions.size(); ++r)
      if (fit.regions[r].name == region) return &fit.verdicts[r];
    return nullptr;
  }

  static inline std::unique_ptr<test::ChartBodies> bodies_;
  static inline std::unique_ptr<SizeFitter> pencil_;
};

}  // namespace

TEST_F(SizeRecommendation, EachWomensChartBodyGetsItsOwnPencilSkirt) {
  const std::vector<ChartSize>& sizes = chart().sizes(Sex::Female);
  for (size_t i = 0; i < sizes.size(); ++i) {
    const Recommendation r = pencil_->recommend(pencil_->graded(Sex::Female, int(i)).body, Sex::Female);
    EXPECT_EQ(r.recommended, sizes[i].name);
    EXPECT_FALSE(r.allTight) << sizes[i].name;
    // The candidates: the chart's nearest (the body's own) and its neighbours.
    EXPECT_EQ(r.sizes.size(), i == 0 || i + 1 == sizes.size() ? 2u : 3u) << sizes[i].name;
  }
}

// Grading a size makes its chart body and garment and drapes nothing: the garment a render
// of that size wears costs no drape. The garment's own fit on its chart body is draped when
// a fit first needs it, and the garment is the same either way.
TEST_F(SizeRecommendation, GradingASizeDrapesNothing) {
  SizeFitter fitter(model(), chart(), *findStyle("pencil"));
  const int m = index(Sex::Female, "M");
  const SizeFitter::Graded& graded = fitter.graded(Sex::Female, m);
  EXPECT_FALSE(fitter.hasOwnFit(Sex::Female, m));
  ASSERT_FALSE(graded.garment.vertices.empty());
  const std::vector<Vec3> garment = graded.garment.vertices;
  EXPECT_FALSE(fitter.ownFit(Sex::Female, m).empty());
  EXPECT_TRUE(fitter.hasOwnFit(Sex::Female, m));
  EXPECT_EQ(fitter.graded(Sex::Female, m).garment.vertices, garment);
  // Its own fit is the one pencil_'s recommendation judged M against (the same drape).
  const std::vector<RegionFit>& own = fitter.ownFit(Sex::Female, m);
  const std::vector<RegionFit>& shared = pencil_->ownFit(Sex::Female, m);
  ASSERT_EQ(own.size(), shared.size());
  for (size_t r = 0; r < own.size(); ++r) {
    EXPECT_EQ(own[r].name, shared[r].name);
    EXPECT_EQ(own[r].meanStrain, shared[r].meanStrain) << own[r].name;
    EXPECT_EQ(own[r].ease, shared[r].ease) << own[r].name;
  }
}

// A size tried on its own chart body is the drape its own fit was measured on, not draped
// again (SizeFitter::coldDrape): the same positions as a cold drape made here, and it fits.
TEST_F(SizeRecommendation, ASizeOnItsOwnChartBodyIsItsOwnFitsDrape) {
  const int m = index(Sex::Female, "M");
  const SizeFitter::Graded& graded = pencil_->graded(Sex::Female, m);
  const SizeFit own = pencil_->tryOn(graded.body, Sex::Female, m);
  EXPECT_TRUE(pencil_->hasOwnFit(Sex::Female, m));
  EXPECT_FALSE(own.drape.report.warm);
  const GarmentDrape again = pencil_->drape(graded.garment, std::make_shared<const MeshCollider>(graded.body));
  EXPECT_EQ(own.drape.positions, again.positions);
  for (const Verdict verdict : own.verdicts) EXPECT_EQ(verdict, Verdict::Fits) << own.text;
}

// The advice figment-size gives is the service's (FitWorker: each candidate draped cold,
// recommendFrom): on this body, between the chart's L and XL, the L pencil skirt started
// from the XL's drape rested 9 % stretched at the waist, held so by friction, where draped
// from its cut shape it fits everywhere: warm, the tool advised XL and the service L.
TEST_F(SizeRecommendation, TheAdviceIsTheServicesEachSizeDrapedFromItsCutShape) {
  const TriangleMesh body = bodies_->human->measuredBody(ChartSize{Sex::Female, "", "", 1.68, 0.94, 0.80, 1.02}).body;
  const Recommendation advice = pencil_->recommend(body, Sex::Female);
  for (const SizeFit& fit : advice.sizes) EXPECT_FALSE(fit.drape.report.warm) << fit.size;
  const auto collider = std::make_shared<const MeshCollider>(body);
  const Recommendation service = pencil_->recommendFrom(body, Sex::Female, [&](int size) {
    return pencil_->drapeGraded(pencil_->graded(Sex::Female, size), Sex::Female, size, collider);
  });
  EXPECT_EQ(advice.recommended, service.recommended);
  EXPECT_EQ(advice.recommended, "L");
}

TEST_F(SizeRecommendation, EachMensChartBodyGetsItsOwnTShirt) {
  SizeFitter tshirt(model(), chart(), *findStyle("tshirt"));
  const std::vector<ChartSize>& sizes = chart().sizes(Sex::Male);
  for (size_t i = 0; i < sizes.size(); ++i)
    EXPECT_EQ(tshirt.recommend(tshirt.graded(Sex::Male, int(i)).body, Sex::Male).recommended, sizes[i].name);
}

// Every style of the catalogue (scenes/catalogue/) in every sex it is sold in: each chart
// body is recommended its own size, but for the exceptions listed here by name with their
// reason (the same list as docs/sizes.md). The pencil skirt (women) and the T-shirt (men)
// are the tests above.
struct Exception {
  const char* style;
  Sex sex;
  const char* body;
  const char* recommended;
  const char* why;
};
constexpr const char* kFlaredSkirtWaistEase =
    "the flared skirt's waist ease (3 cm) is under the chart's 4 cm step: a size down is 1 cm short at the waist, "
    "1 to 2 % stretch in cotton, within its 4 %, and grips as its own size does";
const Exception kExceptions[] = {
    {"skirt", Sex::Female, "XS", "XXS", kFlaredSkirtWaistEase},
    // back since issue 43's solve (the chart bodies within 0.3 mm of their bust level before)
    {"skirt", Sex::Female, "S", "XS", kFlaredSkirtWaistEase},
    // issue 43's sizes: from DOB 46 up the waist steps by 6 cm, twice the skirt's ease; a size
    // down is 3 cm short on a waist of a metre and more, 3 % stretch, within cotton's 4 %
    {"skirt", Sex::Female, "4XL", "3XL", kFlaredSkirtWaistEase},
    {"skirt", Sex::Female, "6XL", "5XL", kFlaredSkirtWaistEase},
    {"skirt", Sex::Female, "7XL", "6XL", kFlaredSkirtWaistEase},
};

TEST_F(SizeRecommendation, EveryCatalogueStyleGivesEachChartBodyItsOwnSizeButTheListedExceptions) {
  const GarmentCatalogue catalogue(defaultCataloguePath());
  for (const CatalogueStyle& style : catalogue.styles())
    for (const Sex sex : style.sexes) {
      if (style.sewn()) continue;  // sewn from patterns: test_SewnSizeRecommendation.cpp
      if ((style.name == "pencil" && sex == Sex::Female) || (style.name == "tshirt" && sex == Sex::Male)) continue;
      SizeFitter fitter(model(), chart(), *findStyle(style.name));
      for (const std::string& size : style.sizes(sex)) {
        std::string expected = size, why;
        for (const Exception& e : kExceptions)
          if (style.name == e.style && sex == e.sex && size == e.body) expected = e.recommended, why = e.why;
        const Recommendation r = fitter.recommend(fitter.graded(sex, index(sex, size)).body, sex);
        EXPECT_EQ(r.recommended, expected) << style.name << " on the " << sexName(sex) << " " << size << " body"
                                           << (why.empty() ? "" : ": listed because " + why);
      }
    }
}

// The body at `position` along the chart (a size's index, fractional; beyond the ends by the
// end steps), as figment-bench recommend --grid makes it.
static TriangleMesh chartBodyAt(MakeHumanLibrary& human, const SizeChart& chart, Sex sex, double position) {
  const std::vector<ChartSize>& sizes = chart.sizes(sex);
  const int i = std::clamp(static_cast<int>(std::floor(position)), 0, static_cast<int>(sizes.size()) - 2);
  const double t = position - i;
  const auto at = [&](double ChartSize::*field) {
    return sizes[i].*field + t * (sizes[i + 1].*field - sizes[i].*field);
  };
  return human
      .measuredBody(ChartSize{sex, "", "", at(&ChartSize::stature), at(&ChartSize::bust), at(&ChartSize::waist),
                              at(&ChartSize::hip)})
      .body;
}

// Bodies along the chart between its sizes, from half a size under XS to half a size over
// L (a small grid: figment-bench recommend --grid 30 runs the issue's 30 bodies).
TEST_F(SizeRecommendation, NeverSmallerAsTheBodyGrows) {
  int previous = -1;
  for (double position = 0.5; position <= 4.51; position += 0.5) {
    const TriangleMesh body = chartBodyAt(*bodies_->human, chart(), Sex::Female, position);
    const int recommended = index(Sex::Female, pencil_->recommend(body, Sex::Female).recommended);
    EXPECT_GE(recommended, previous) << "at " << position;
    previous = recommended;
  }
}

// The same over issue 43's sizes: from half a size over XL (DOB 42) to half a size under 7XL
// (DOB 54), where the chart's steps grow to 6 cm in bust and waist.
TEST_F(SizeRecommendation, NeverSmallerAsTheBodyGrowsPastXl) {
  ASSERT_EQ(chart().sizes(Sex::Female).size(), 12u);
  int previous = -1;
  for (double position = 5.5; position <= 10.51; position += 0.5) {
    const TriangleMesh body = chartBodyAt(*bodies_->human, chart(), Sex::Female, position);
    const int recommended = index(Sex::Female, pencil_->recommend(body, Sex::Female).recommended);
    EXPECT_GE(recommended, previous) << "at " << position;
    EXPECT_GE(recommended, 5) << "at " << position;  // never under the XL the body is past
    previous = recommended;
  }
}

// Two neighbours of the issue's grid (--grid 30 --grid-beyond 2: positions -2 + 9 k / 29),
// men's, at k = 13 and 14, just over M: the M skirt's thighs were told "2 cm too high" on
// the first (its row nearest the crotch 2.1 cm lower on the M chart body than on this one),
// every candidate was tight, and the largest, L, was recommended before M.
TEST_F(SizeRecommendation, NeverSmallerBetweenTheMensGridBodiesJustOverM) {
  std::vector<int> recommended;
  for (const int k : {13, 14}) {
    const TriangleMesh body = chartBodyAt(*bodies_->human, chart(), Sex::Male, -2.0 + 9.0 * k / 29.0);
    const Recommendation r = pencil_->recommend(body, Sex::Male);
    EXPECT_FALSE(r.allTight) << "k = " << k;
    recommended.push_back(index(Sex::Male, r.recommended));
  }
  EXPECT_EQ(recommended[0], index(Sex::Male, "M"));
  EXPECT_GE(recommended[1], recommended[0]);
}

// The issue's grid's first two women's bodies, two sizes under XXS (k = 0 and 1): the
// first was recommended XS before the second's XXS, every candidate "tight at the waist",
// because its underbust was found on the ribcage's foot 8 cm under the fold (the lowest
// front of a flat chest's window), so the waist region's top, midway to it, fell 4 cm.
TEST_F(SizeRecommendation, NeverSmallerBetweenTheWomensGridBodiesTwoSizesUnderXxs) {
  std::vector<int> recommended;
  for (const int k : {0, 1}) {
    const TriangleMesh body = chartBodyAt(*bodies_->human, chart(), Sex::Female, -2.0 + 9.0 * k / 29.0);
    const BodyMeasurements m = measureBody(body, {"underbust_girth"});
    EXPECT_GT(m.landmarks.underbust, m.landmarks.bust - 0.05) << "k = " << k;
    const Recommendation r = pencil_->recommend(body, Sex::Female);
    EXPECT_FALSE(r.allTight) << "k = " << k << ": " << r.sizes.front().text;
    recommended.push_back(index(Sex::Female, r.recommended));
  }
  EXPECT_EQ(recommended[0], index(Sex::Female, "XXS"));
  EXPECT_GE(recommended[1], recommended[0]);
}

// How many of `drape`'s nodes lie more than 5 mm inside `body`: none where it was draped on
// that body (the solver holds its nodes out), many for a drape made on a smaller one.
static int nodesDeepInside(const std::vector<Vec3>& drape, const TriangleMesh& body) {
  const MeshCollider collider(body);
  int inside = 0;
  for (const Vec3& p : drape) {
    Contact contact;
    inside += collider.contact(p, 0.0, 0.05, contact) && contact.distance < -0.005;
  }
  return inside;
}

TEST_F(SizeRecommendation, SmallOnTheXlBodyIsTightAndXlOnTheSmallBodyLoose) {
  const TriangleMesh& xl = pencil_->graded(Sex::Female, index(Sex::Female, "XL")).body;
  const SizeFit tight = pencil_->tryOn(xl, Sex::Female, index(Sex::Female, "S"));
  for (const char* region : {"waist", "hips"}) {
    ASSERT_NE(verdictAt(tight, region), nullptr) << region;
    EXPECT_EQ(*verdictAt(tight, region), Verdict::Tight) << region << ": " << tight.text;
  }
  EXPECT_NE(tight.text.find("tight at the hips"), std::string::npos) << tight.text;
  // S was draped on the XL body, not handed its drape on its own chart body (SizeFitter's
  // own drape is for that body alone).
  EXPECT_EQ(nodesDeepInside(tight.drape.positions, xl), 0);
  const TriangleMesh& s = pencil_->graded(Sex::Female, index(Sex::Female, "S")).body;
  const SizeFit loose = pencil_->tryOn(s, Sex::Female, index(Sex::Female, "XL"));
  for (const char* region : {"waist", "hips", "thighs"}) {
    ASSERT_NE(verdictAt(loose, region), nullptr) << region;
    EXPECT_EQ(*verdictAt(loose, region), Verdict::Loose) << region << ": " << loose.text;
  }
  // The tight one stretches and presses more than the loose one, which stands off further.
  EXPECT_GT(tight.regions[1].meanStrain, loose.regions[1].meanStrain);
  EXPECT_GT(tight.regions[1].pressure, loose.regions[1].pressure);
  EXPECT_LT(tight.regions[1].ease, loose.regions[1].ease);
}

TEST_F(SizeRecommendation, FigmentSizePrintsTheIssuesJson) {
  const test::TempDir dir;
  const test::ProgramResult run =
      test::runProgram(std::string(FIGMENT_BINARY_DIR) + "/bin/figment-size",
                       "--style pencil --sex female --stature 1.68 --bust-girth 0.88 --waist-girth 0.72 "
                       "--hip-girth 0.96 --json",
                       dir.path(), dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.out.rfind("{\"recommended\": \"M\"", 0), 0u) << run.out;
  for (const char* key : {"\"sizes\": {\"S\": {", "\"L\": {", "\"regions\": {\"waist\": {\"stretch_pct\": ",
                          "\"ease_mm\": ", "\"pressure_kpa\": ", "\"verdict\": \"tight\"", "\"verdict\": \"fits\""})
    EXPECT_NE(run.out.find(key), std::string::npos) << key << " in " << run.out;
}

TEST_F(SizeRecommendation, FigmentSizeTriesOneSizeOn) {
  const test::TempDir dir;
  const test::ProgramResult run =
      test::runProgram(std::string(FIGMENT_BINARY_DIR) + "/bin/figment-size",
                       "--style pencil --sex female --stature 1.68 --bust-girth 0.84 --waist-girth 0.68 "
                       "--hip-girth 0.92 --size XL --json",
                       dir.path(), dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.out.rfind("{\"sizes\": {\"XL\": {", 0), 0u) << run.out;
  EXPECT_EQ(run.out.find("recommended"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"verdict\": \"loose\""), std::string::npos) << run.out;
  // The catalogue's name for that garment tries the same size on.
  const test::ProgramResult named =
      test::runProgram(std::string(FIGMENT_BINARY_DIR) + "/bin/figment-size",
                       "--style pencil:XL --sex female --stature 1.68 --bust-girth 0.84 --waist-girth 0.68 "
                       "--hip-girth 0.92 --json",
                       dir.path(), dir.path());
  ASSERT_EQ(named.status, 0) << named.err;
  EXPECT_EQ(named.out.rfind("{\"sizes\": {\"XL\": {", 0), 0u) << named.out;
}

TEST_F(SizeRecommendation, FigmentSizeRefusesBadInputInOneLine) {
  const test::TempDir dir;
  const std::string tool = std::string(FIGMENT_BINARY_DIR) + "/bin/figment-size";
  const test::ProgramResult style =
      test::runProgram(tool, "--style gown --sex female --body x.obj", dir.path(), dir.path());
  EXPECT_EQ(style.status, 1);
  EXPECT_EQ(style.err,
            "figment-size: --style gown: not one of dress, skirt, tshirt, pencil, tee, shirt, trousers, pencilskirt, "
            "circleskirt, sundress (or a catalogue garment, style:size)\n");
  // A catalogue garment's name (scenes/catalogue/) that names no size it is sold in.
  const test::ProgramResult garment =
      test::runProgram(tool, "--style dress:Q --sex female --body x.obj", dir.path(), dir.path());
  EXPECT_EQ(garment.status, 1);
  EXPECT_EQ(garment.err,
            "figment-size: --style \"dress:Q\": no size Q of dress (female XXS, XS, S, M, L, XL, XXL, 3XL, 4XL, 5XL, "
            "6XL, 7XL)\n");
  const test::ProgramResult some =
      test::runProgram(tool, "--style dress --sex female --stature 1.68", dir.path(), dir.path());
  EXPECT_EQ(some.status, 1);
  EXPECT_EQ(some.err,
            "figment-size: give --body FILE, or all of --stature, --bust-girth, --waist-girth and --hip-girth\n");
  const test::ProgramResult far = test::runProgram(
      tool, "--style dress --sex female --stature 1.68 --bust-girth 0.88 --waist-girth 0.9 --hip-girth 0.5", dir.path(),
      dir.path());
  EXPECT_EQ(far.status, 1);
  const test::ProgramResult size = test::runProgram(
      tool, "--style pencil --sex male --stature 1.74 --bust-girth 0.96 --waist-girth 0.84 --hip-girth 1.0 --size XXS",
      dir.path(), dir.path());
  EXPECT_EQ(size.status, 1);
  EXPECT_EQ(size.err, "figment-size: --size XXS: no male size of that name\n");
  EXPECT_EQ(std::count(far.err.begin(), far.err.end(), '\n'), 1) << far.err;
  EXPECT_TRUE(far.out.empty());
}
