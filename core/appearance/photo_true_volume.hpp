#pragma once
// The photo-true colour volume (issue 17): the block's wood as a volume of colours made of the photos'
// own texture, re-grown along the fitted field, for `export --quantity color` of a photo-true project.
//
// How: the volume is a stack of slices across the fibres, synthesised one after another
// (GuidedSliceSynthesis, appearance/guided_synthesis.hpp). The slices are stacked along the block axis
// nearest to the fibres, so each slice is end grain or close to it; the first slice is synthesised as any
// surface, and each later one starts from the one before, carried along the fibre, so that the pores and
// rays of a slice go on into the next: pores become tubes along the fibres, rays radial ribbons, and a
// cut through the volume along the grain shows them as streaks. The guidance (ring phase, sawing angles,
// sapwood) comes from the field at every voxel, so the rings are where the field puts them.
// Why not Kopf et al. 2007's solid synthesis, which matches three orthogonal slices through every voxel:
// at the photos' resolution a 40 mm cube is 256^3 voxels, each matched three times per pass, which is
// tens of minutes on two cores; the stack costs one finest-level pass per voxel (docs/export.md).
// What it does not do: the slices along the grain are not matched against the side-grain photos, so a
// long-grain cut of the volume shows the end grain's pores drawn out along the fibres (for ring-porous
// wood close to what a plane shows; the side-grain sheen and the rays' fleck are not there).
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace kerf {

struct PhotoTrueVolume {
  glm::ivec3 size{0};             // samples along x, y, z
  glm::vec3 origin{0.0f};         // block mm of sample (0, 0, 0)'s centre
  glm::vec3 spacing{0.0f};        // block mm between samples
  int sliceAxis = 2;              // the axis the slices were stacked along (the one nearest the fibres)
  std::vector<std::uint8_t> rgb;  // 8-bit colour per sample, x fastest, then y, then z

  // Trilinear between the samples, clamped at the volume's outer sample centres; 0..1.
  glm::vec3 colourAt(glm::vec3 pMm) const;
};

}  // namespace kerf
