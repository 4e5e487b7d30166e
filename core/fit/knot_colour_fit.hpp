#pragma once
// The knots' colour from the photos (issue 19 item 4: darker branch wood, as the photos show it). Inside a
// knot's outline on a photo (rings/knot_outline.hpp) lies branch wood; just around it, stem wood of about
// the same growth time. Larsson et al. 2022 Sec. 4.3 darken a knot by subtracting knots.darkening from the
// wood's colour, so that colour is fitted as the median colour around the outlines minus the median colour
// inside them (inside 0.6 of each ellipse, around 1.3-2 times it), per channel, over every outline found,
// within the schema's range. Without an outline the schema's value stays.
#include <array>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "geometry/block.hpp"
#include "image/image.hpp"
#include "rings/knot_outline.hpp"

namespace kerf {

struct KnotColourFit {
  bool fitted = false;
  glm::vec3 darkening{0.0f};   // knots.darkening (RGB, the photos' colour units)
  glm::vec3 knotColour{0.0f};  // the medians it came from: inside the outlines
  glm::vec3 woodColour{0.0f};  // and around them
  int outlines = 0;            // outlines used
  std::string note;            // why none was fitted
};

KnotColourFit fitKnotDarkening(const std::array<Image, 6>& photos, const Block& block,
                               const std::vector<KnotOutline>& outlines);

}  // namespace kerf
