// The tiny stability study (tests/studies/data/tiny-stability.toml): f = 30 and 40 Hz,
// Gamma = 3, 5, 6.
//
// A plate that moves less than half a particle diameter (amplitude A = Gamma g / (2 pi f)^2)
// cannot move a layer's particles past their neighbours: the layer stays caged, crystal or
// amorphous, never liquid-like (the paper's argument for the crystals at high f, Huang,
// Sec. III: the amplitude falls as f^-2 and becomes small against d). Checked at every grid
// point with A < d/2, dry and wet, on the most frequent verdict of the seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "scene/SceneParser.hpp"
#include "tests/studies/framework/TinyStudy.hpp"

namespace {

constexpr char kKind[] = "stability";
using StabilityResults = granwave::testing::TinyStudyTest<kKind>;
const std::string kRoot = "/results/stability";
constexpr double kLiquidLike = 2;  // /results/stability/<law>/state code

TEST_F(StabilityResults, LayersOnAPlateMovingLessThanHalfADiameterStayCaged) {
  const auto f = study().series(kRoot + "/frequencies");
  const auto gammas = study().series(kRoot + "/gammas");
  const granwave::Scene scene =
      granwave::parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-dry.toml");
  const double d = scene.particles.diameter;
  int checked = 0;
  for (const char* law : {"dry", "wet"}) {
    const auto state = study().series(kRoot + "/" + law + "/state");
    for (std::size_t k = 0; k < state.size(); ++k) {
      const std::size_t i = k / gammas.size(), j = k % gammas.size();
      const double omega = 2 * std::numbers::pi * f[i];
      const double amplitude = gammas[j] * scene.run.gravity / (omega * omega);
      if (amplitude >= d / 2 || !std::isfinite(state[k])) continue;
      ++checked;
      EXPECT_NE(state[k], kLiquidLike) << law << " at f = " << f[i] << " Hz, Gamma = " << gammas[j];
    }
  }
  EXPECT_GE(checked, 4) << "too few points with A < d/2 classified";
}

}  // namespace
