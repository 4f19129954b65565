#include "core/process/process.h"

namespace fissure {

std::string to_string(Field f) {
  switch (f) {
    case Field::BlockGeometry: return "block_geometry";
    case Field::BlockKinematics: return "block_kinematics";
    case Field::BlockStress: return "block_stress";
    case Field::Contacts: return "contacts";
    case Field::FractureFlow: return "fracture_flow";
    case Field::PressureLoads: return "pressure_loads";
  }
  return "unknown";
}

}  // namespace fissure
