// Scenes of dynamic DDA under ground motion (docs/dda.md section 10), built
// as scene text with their records written beside them: a layer of glued
// blocks on a viscous base, and a block on a driven base.
#pragma once

#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace fissure::testing {

/// Samples of a base motion: times (s) and horizontal and vertical values.
struct MotionSamples {
  std::vector<double> t, x, y;
};

/// A horizontal layer of `layers` glued blocks (a column far wider than
/// tall, so that it shears as a 1D layer) of `soil` on a viscous base whose
/// medium beyond is `bedrock`; the outcrop velocity `outcrop` enters
/// through the base (free-field input). Monitor `top` at the surface. No
/// gravity.
struct LayerSpec {
  double height = 100, width = 1000;  ///< m
  int layers = 50;
  double density = 2700, poisson_ratio = 0.25;
  double soil_modulus = 10e9, bedrock_modulus = 10e9;           ///< Pa
  double penalty = 1e13;                                        ///< N/m
  double time_step = 1e-4, end = 0.35, output_interval = 5e-4;  ///< s
};
Scene layer_on_viscous_base(const LayerSpec& spec, const MotionSamples& outcrop_velocity,
                            const std::string& dir);

/// A 1 x 0.5 m block at rest, centred on the origin, on a fixed 40 x 2 m base
/// whose plane rises towards +x at `slope`, Coulomb friction
/// `friction_angle`; the base follows the acceleration record `base` (no
/// baseline correction). Monitors `block` (its centroid) and `base`.
struct ShakenBlockSpec {
  double slope = 0, friction_angle = 30;                     ///< deg
  double time_step = 1e-3, end = 2, output_interval = 0.01;  ///< s
  double penalty = 5e9;                                      ///< N/m
};
Scene block_on_shaken_plane(const ShakenBlockSpec& spec, const MotionSamples& base_acceleration,
                            const std::string& dir);

/// The shear wave speed of a material of the layer spec's (plane strain or
/// stress alike): sqrt(G / rho).
double shear_wave_speed(double modulus, double poisson_ratio, double density);

}  // namespace fissure::testing
