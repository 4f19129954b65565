// Processes meet through fields, not names (docs/architecture.md 2 and
// "Adding a process"): a second block-mechanics process registered under
// a name of its own ("stand_in_blocks"; the explicit DEM is one) that writes the
// same fields as the DDA (here a stand-in that runs the DDA inside) gets
// the HM coupling of the flow and the thermal joint closure the DDA gets,
// to the bit, without any module knowing its name.
//  * HM: the HM stack of docs/flow.md section 7, its monitors with the
//    stand-in the same bytes as with the mechanics.
//  * Thermal joint closure: a lid on a fixed base, heated from the base,
//    the lid leaving at 1 cm/s. While the faces touch they conduct; once
//    the contact opens no heat crosses. With the stand-in the lid stays as
//    cold as with the mechanics (the same bytes), far colder than without
//    a block process (the faces then conduct throughout).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "coupling/process_registry.h"
#include "mechanics/dda/create_dda_process.h"
#include "mechanics/dda/dda_settings.h"
#include "rockmass/fields/pressure_loads.h"
#include "tests/support/flow_networks.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {
namespace {

constexpr const char* kStandInName = "stand_in_blocks";

/// The DDA under another name: what the framework and the other processes
/// see of it is its name, its section and the fields it writes.
class StandInBlockProcess final : public Process {
 public:
  explicit StandInBlockProcess(const Scene& scene) : dda_(dda::create_dda_process(scene)) {}
  std::string name() const override { return kStandInName; }
  std::vector<std::string> reads() const override { return dda_->reads(); }
  std::vector<std::string> writes() const override { return dda_->writes(); }
  void initialize(RockMass& state) override { dda_->initialize(state); }
  double proposed_dt(const RockMass& state) const override { return dda_->proposed_dt(state); }
  StepReport advance(RockMass& state, double t, double dt) override {
    return dda_->advance(state, t, dt);
  }
  const MonitorSource* monitors() const override { return dda_->monitors(); }
  ResultsPart* results() override { return dda_->results(); }
  nlohmann::json statistics() const override { return dda_->statistics(); }
  nlohmann::json energy(const RockMass& state) const override { return dda_->energy(state); }
  void save(CheckpointWriter& out, const RockMass& state) const override { dda_->save(out, state); }
  void restore(CheckpointReader& in, RockMass& state) override { dda_->restore(in, state); }

 private:
  std::unique_ptr<Process> dda_;
};

std::unique_ptr<Process> create_stand_in(const Scene& scene) {
  return std::make_unique<StandInBlockProcess>(scene);
}

/// Its section `stand_in_blocks` is read as the DDA's `mechanics` section (the DDA
/// inside reads its settings from there) and declares the same fields.
const SectionReader kStandInSection{
    kStandInName, "a stand_in_blocks section",    dda::kMechanicsSection.read, nullptr, {}, {},
    false,        dda::kMechanicsSection.provides};

void register_stand_in() {
  static const bool registered = [] {
    register_process_type({kStandInName, &kStandInSection, &create_stand_in});
    return true;
  }();
  (void)registered;
}

TEST(StandInBlockProcess, TheFlowCouplesToItsBlocksAsToTheMechanics) {
  register_stand_in();
  StackParameters p;
  p.end_time = 0.02;
  Scene with_mechanics = hm_stack_scene(p);
  with_mechanics.coupling.order = {"mechanics", "flow"};
  Scene with_stand_in = with_mechanics;
  with_stand_in.physics = {kStandInName, "flow"};
  with_stand_in.coupling.order = {kStandInName, "flow"};
  const RunResult a = run_scene(with_mechanics, "stand_in_hm_mechanics");
  const RunResult b = run_scene(with_stand_in, "stand_in_hm_dem");
  ASSERT_EQ(a.summary.status, "completed") << a.summary.message;
  ASSERT_EQ(b.summary.status, "completed") << b.summary.message;
  // The flow loads the stand-in's block walls and reads its apertures.
  EXPECT_TRUE(b.state.fields.find(kPressureLoads)) << "no pressures on the blocks";
  EXPECT_EQ(file_bytes(b.outdir + "/monitors.csv"), file_bytes(a.outdir + "/monitors.csv"));
}

std::string lid_scene(const std::string& physics) {
  std::string s = "physics: " + physics + R"(
gravity: [0, 0]
materials:
  - {name: rock, density: 2650 kg/m^3, young_modulus: 10 GPa, poisson_ratio: 0.25}
joints:
  - {name: joint, friction_angle: 30}
blocks:
  - {name: base, vertices: [[0, 0], [2, 0], [2, 1], [0, 1]], fixed: true}
  - {name: lid, vertices: [[0, 1], [2, 1], [2, 2], [0, 2]], initial_velocity: [0, 1 cm/s, 0]}
monitors:
  - {name: lid, point: [1, 1.8]}
thermal:
  materials:
    - {name: rock, conductivity: 300 W/m/K, heat_capacity: 1 kJ/m^3/K}
  mesh: {element_size: 0.25 m}
  time_step: 20 ms
  initial: {temperature: 15}
  joints: {conductance: 1e5 W/m^2/K}
  sources:
    - {name: heater, point: [1, 0.3], power: 10 kW/m}
time: {end: 1 s}
output: {interval: 0.5 s, hdf5: false}
)";
  const std::string block_process = physics.substr(1, physics.find(',') - 1);
  if (physics.find(',') != std::string::npos)
    s += block_process + ": {dda: {time_step: 5 ms}}\ncoupling: {order: [" + block_process +
         ", thermal]}\n";
  return s;
}

/// The lid's temperature at the end (summary.json's monitors).
double lid_temperature(const RunResult& r) {
  return r.summary.monitors["lid"]["T"].get<double>();
}

TEST(StandInBlockProcess, ItsOpenJointsStopTheHeatAsTheMechanicssDo) {
  register_stand_in();
  const RunResult alone =
      run_scene(read_scene_text(lid_scene("[thermal]"), "alone.yaml"), "stand_in_lid_alone");
  const RunResult dda = run_scene(read_scene_text(lid_scene("[mechanics, thermal]"), "dda.yaml"),
                                  "stand_in_lid_mechanics");
  const RunResult dem =
      run_scene(read_scene_text(lid_scene("[stand_in_blocks, thermal]"), "stand_in.yaml"),
                "stand_in_lid_dem");
  for (const RunResult* r : {&alone, &dda, &dem})
    ASSERT_EQ(r->summary.status, "completed") << r->summary.message;
  const double conducting = lid_temperature(alone), opened = lid_temperature(dda);
  EXPECT_GT(conducting - 15, 10 * (opened - 15))
      << "the lid warms through its face when no block process opens it (" << conducting
      << " degC), far less once it has left (" << opened << " degC)";
  EXPECT_EQ(file_bytes(dem.outdir + "/monitors.csv"), file_bytes(dda.outdir + "/monitors.csv"));
}

}  // namespace
}  // namespace fissure::testing
