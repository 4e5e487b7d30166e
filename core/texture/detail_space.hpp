#pragma once
// The detail parameters the texture inference searches (Mokume A.2.3: pores, rays, fibres and the
// early-to-late transition): the schema's parameters with a search range (the `search` column of
// params/wood_parameters.def), in schema order, each mapped to a unit coordinate u in [0, 1] over that
// range: sizes on a log scale (a pore twice as large is as far as one half as large), shares and strengths
// linearly. Two more coordinates, searched last, are not schema parameters: "rays.lightness" sets the ray
// colour as a multiple of the earlywood colour (rays are lighter or darker than the wood around them; one
// number instead of an RGB), and "color.latewood_contrast" multiplies both latewood colours (heartwood and
// sapwood) of the parameters it is decoded onto (it always encodes as 1): the colour fit alone may leave
// latewood almost as light as earlywood when the rings do not line up to the pixel, and pores darken only
// through that contrast.
#include <string>
#include <vector>

#include "params/parameter_schema.hpp"

namespace kerf {

struct DetailCoordinate {
  std::string id;  // schema id, or "rays.lightness"
  bool logScale = false;
  float lo = 0, hi = 1;  // the value range u = 0..1 covers
};

// Every detail coordinate the inference knows, in search order.
std::vector<DetailCoordinate> allDetailCoordinates();
// The coordinates of `ids` (InputError naming an unknown one); empty ids: all.
std::vector<DetailCoordinate> detailCoordinates(const std::vector<std::string>& ids);

float detailValue(const WoodParameters& params, const DetailCoordinate& coordinate);
void setDetailValue(WoodParameters& params, const DetailCoordinate& coordinate, float value);

// The unit coordinates of params (clamped to [0, 1]) and back.
std::vector<double> encodeDetail(const WoodParameters& params,
                                 const std::vector<DetailCoordinate>& coordinates);
WoodParameters decodeDetail(const WoodParameters& base, const std::vector<DetailCoordinate>& coordinates,
                            const std::vector<double>& u);

// The coarse search's three size knobs (Mokume A.2.3: fibre, pore and ray sizes): every length of that
// feature multiplied by `factor` (pores: radii and spacing; rays: spacing, thickness and height; fibres:
// width and length), kept inside the hard ranges.
enum class DetailFeature { Fibres, Pores, Rays };
void scaleDetailSize(WoodParameters& params, DetailFeature feature, float factor);

}  // namespace kerf
