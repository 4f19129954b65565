// The scene's `thermal.convection` (docs/scene-reference.md section 12,
// docs/thermal.md 7): the heat the water in the fractures carries
// (theory.md 4.2). Validated values in SI units; read by
// read_convection_settings.cpp; each default is written here, once.
#pragma once

#include <string>
#include <vector>

namespace fissure {

/// Water entering the network at the nodes of a named boundary of the
/// fracture graph (thermal.convection.inlets[]).
struct FluidInlet {
  std::string boundary;    ///< left, right, bottom, top, or a flow region's name
  double temperature = 0;  ///< degC
  std::string path;        ///< "file:line:column: thermal.convection.inlets[0]"
};

struct FractureConvection {
  /// Nu of h = Nu lambda_f / (2 e) (e: the segment's mean hydraulic
  /// aperture); 8.23: laminar flow between plates, uniform flux.
  double nusselt = 8.23;
  /// The limit h -> infinity: the water has its walls' temperature (the
  /// wall nodes and the fluid node at each place are one unknown).
  bool wall_temperature = false;
  double density = 1000;        ///< rho_f, kg/m^3
  double specific_heat = 4200;  ///< c_f, J/(kg K)
  double conductivity = 0.6;    ///< lambda_f, W/(m K)
  std::vector<FluidInlet> inlets;
  std::string path = "thermal.convection";  ///< for run-time messages

  double volumetric_heat() const { return density * specific_heat; }
};

}  // namespace fissure
