// Bad continuum input (issue 24, "Bad input"): non-physical parameters and
// conditions that leave the problem singular are located errors before
// anything runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "continuum/poroelasticity/continuum_settings.h"
#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"
#include "tests/support/run_scene.h"

namespace fissure {
namespace {

using testing::at;
using testing::expect_contains;
using testing::parse_error;
using testing::replace;
using testing::start_error;

const std::string kScene = R"(name: bad_continuum
physics: [continuum]
gravity: [0, 0]
materials:
  - {name: clay, density: 2000, young_modulus: 1 GPa, poisson_ratio: 0.25}
time: {end: 1000 s}
continuum:
  domain: [[0, 0], [1, 0], [1, 10], [0, 10]]
  mesh: {divisions: [1, 10]}
  materials:
    - {name: clay, biot_coefficient: 1, biot_modulus: 10 GPa, permeability: 1e-15 m^2}
  conditions:
    - {boundary: left, displacement: [0, free]}
    - {boundary: bottom, displacement: [0, 0]}
    - {boundary: top, traction: [0, -1 MPa]}
    - {boundary: top, pressure: 0}
  time_step: 100 s
)";

TEST(continuum_bad_input, TheValidSceneStarts) {
  EXPECT_EQ(parse_error(kScene), "");
  EXPECT_EQ(start_error(kScene), "");
}

TEST(continuum_bad_input, NonPhysicalParametersAreLocated) {
  std::string s = replace(kScene, "poisson_ratio: 0.25", "poisson_ratio: 0.5");
  expect_contains(parse_error(s),
                  "materials[0].poisson_ratio: found '0.5'; expected a number in (-1, 0.5)");
  s = replace(kScene, "biot_coefficient: 1", "biot_coefficient: 1.5");
  expect_contains(parse_error(s), at(s, "1.5"));
  s = replace(kScene, "permeability: 1e-15 m^2", "permeability: -1e-15 m^2");
  expect_contains(parse_error(s), at(s, "-1e-15"));
  s = replace(kScene, "permeability: 1e-15 m^2", "permeability: [1e-15, 1e-15, 2e-15]");
  expect_contains(parse_error(s), "symmetric positive definite");
  s = replace(kScene, "[[0, 0], [1, 0], [1, 10], [0, 10]]", "[[0, 0], [1, 10], [1, 0], [0, 10]]");
  expect_contains(parse_error(s), "expected a simple polygon");
}

TEST(continuum_bad_input, ConditionsThatLeaveARigidMotionFreeAreRefused) {
  // Without the bottom the column may slide along y.
  const std::string s = replace(kScene, "    - {boundary: bottom, displacement: [0, 0]}\n", "");
  const std::string e = start_error(s);
  expect_contains(e, "bad.yaml:8:3: continuum.conditions");
  expect_contains(e, "free to move rigidly (a translation along y)");
}

// The linear solver's map: the fracture network's own `pcg` is refused, and so
// are PETSc options with a direct solver, at their lines.
TEST(continuum_bad_input, LinearSolverSettingsAreLocated) {
  const std::string valid =
      replace(kScene, "  time_step: 100 s\n",
              "  time_step: 100 s\n  solver: {type: petsc, petsc_options: \"-ksp_monitor\"}\n");
  EXPECT_EQ(parse_error(valid), "");
  std::string s = replace(valid, "type: petsc", "type: pcg");
  std::string e = parse_error(s);
  expect_contains(e, at(s, "{type: pcg"));
  expect_contains(e,
                  "found solver type 'pcg', which is the fracture network's; expected auto, "
                  "direct or petsc");
  s = replace(valid, "type: petsc", "type: direct");
  e = parse_error(s);
  expect_contains(e, "continuum.solver.petsc_options");
  expect_contains(e, "found PETSc options with solver type 'direct'");
  // Refinement is the direct solvers' (issue 41): one of three words, and
  // refused with the Krylov solvers.
  s = replace(kScene, "  time_step: 100 s\n",
              "  time_step: 100 s\n  solver: {refinement: always}\n");
  EXPECT_EQ(parse_error(s), "");
  s = replace(s, "refinement: always", "refinement: twice");
  e = parse_error(s);
  expect_contains(e, at(s, "twice"));
  expect_contains(e, "expected one of: auto, always, never");
  s = replace(valid, "type: petsc,", "type: petsc, refinement: never,");
  e = parse_error(s);
  expect_contains(e, "continuum.solver.refinement");
  expect_contains(e,
                  "found refinement with solver type 'petsc', whose Krylov solvers do not refine");
}

// A time step that is there but not usable is reported where it is, not
// as a missing key (issue 35).
TEST(continuum_bad_input, ATimeStepThatIsThereIsNotReportedMissing) {
  for (const std::string value : {".nan", "0", "-1 h"}) {
    const std::string s = replace(kScene, "time_step: 100 s", "time_step: " + value);
    const std::string e = parse_error(s);
    expect_contains(e, at(s, "time_step: " + value, 11) + ": continuum.time_step: found '");
    EXPECT_EQ(e.find("key is missing"), std::string::npos) << e;
  }
}

// Options PETSc refuses (issue 35): the error names them and their scene
// line, not "PETSc error 86 in KSPSetFromOptions".
TEST(continuum_bad_input, PetscOptionsPetscRefusesAreLocated) {
  const std::string s = replace(
      kScene, "  time_step: 100 s\n",
      "  time_step: 100 s\n  solver: {type: petsc, petsc_options: \"-ksp_type nonsense\"}\n");
  const std::string e = start_error(s);
  expect_contains(e, at(s, "\"-ksp_type nonsense"));
  expect_contains(e,
                  "continuum.solver.petsc_options: found petsc_options \"-ksp_type nonsense\", "
                  "which PETSc refuses (Unable to find requested KSP type nonsense");
}

// A factorization chosen by the options (-ksp_type preonly) is checked
// by its residual (issue 41: PETSc's Cholesky of the monolithic system,
// which is not symmetric, returned -7.8e43 Pa without a word): one that
// solves nothing (here a Jacobi sweep) is a located error, not an answer.
TEST(continuum_bad_input, APetscFactorizationThatSolvesNothingIsRefused) {
  const std::string s = replace(
      kScene, "  time_step: 100 s\n",
      "  time_step: 100 s\n  solver: {type: petsc, petsc_options: \"-ksp_type preonly -pc_type "
      "jacobi\"}\n");
  const std::string e = start_error(s);
  expect_contains(e, at(s, "{type: petsc"));
  expect_contains(e, "which is no solution; expected a factorization that suits the matrix");
  // (A factorization that suits it passes: MUMPS's LU in
  // verification.ContinuumMpi.TwoRanksGiveTheOneRankAnswer.)
}

TEST(continuum_bad_input, TooLargeAMeshIsRefusedBeforeMeshing) {
  const std::string s = replace(kScene, "divisions: [1, 10]", "divisions: [100000, 100000]");
  expect_contains(start_error(s), "expected at most continuum.mesh.max_elements");
}

TEST(continuum_bad_input, FeaturesOutsideTheDomainAreLocated) {
  std::string s = replace(kScene, "  time_step: 100 s\n",
                          "  time_step: 100 s\n  holes: [{name: drift, polygon: [[0.5, 9], [2, 9], "
                          "[2, 9.5]]}]\n");
  expect_contains(parse_error(s), "expected a hole inside the domain");
  s = replace(kScene, "  time_step: 100 s\n",
              "  time_step: 100 s\n  boundaries: [{name: arc, line: [[0.5, 5], [1, 5]]}]\n");
  expect_contains(parse_error(s), "is not on the domain's outline");
  s = replace(kScene, "  time_step: 100 s\n",
              "  time_step: 100 s\n  boundaries: [{name: top, line: [[1, 0], [1, 10]]}]\n");
  expect_contains(parse_error(s), "found the boundary name 'top' again");
  s = replace(kScene, "  time_step: 100 s\n",
              "  time_step: 100 s\n  sources: [{point: [3, 3], power: 10 W/m}]\n");
  expect_contains(parse_error(s), "outside continuum.domain");
  s = replace(kScene, "  domain: [[0, 0], [1, 0], [1, 10], [0, 10]]",
              "  geometry: axisymmetric\n  domain: [[-1, 0], [1, 0], [1, 10], [-1, 10]]");
  expect_contains(parse_error(s), "expected x = r >= 0 with geometry: axisymmetric");
  // A region wholly outside left nodes of no element (a singular mechanics
  // matrix, reported without a location: fuzz case 139 of issue 34); one
  // across the outline gave CGAL's crossing constraints.
  for (const std::string polygon : {"[[5, 5], [6, 5], [6, 6]]", "[[0.5, 1], [2, 1], [2, 2]]"}) {
    s = replace(kScene, "  time_step: 100 s\n",
                "  time_step: 100 s\n  regions: [{name: lens, material: clay, polygon: " + polygon +
                    "}]\n");
    expect_contains(parse_error(s), "expected a region inside the domain");
  }
  // On the outline is inside: a layer across the whole width.
  s = replace(kScene, "  time_step: 100 s\n",
              "  time_step: 100 s\n  regions: [{name: layer, material: clay, polygon: [[0, 2], [1, "
              "2], [1, 4], [0, 4]]}]\n");
  EXPECT_EQ(parse_error(s), "");
}

// Heat transfer and fluid sources (docs/continuum.md 4): a valid pair
// starts; a negative heat transfer coefficient, a missing ambient
// temperature, a source with both a power and a fluid rate and one with
// neither are located errors.
TEST(continuum_bad_input, HeatTransferAndFluidSourcesAreChecked) {
  const std::string valid =
      replace(kScene, "    - {boundary: top, pressure: 0}\n",
              "    - {boundary: top, pressure: 0}\n"
              "    - {boundary: right, heat_transfer: {coefficient: 10 W/m^2/K, temperature: 20}}\n"
              "  sources: [{name: well, point: [0.5, 5], fluid_rate: 1e-6 m^2/s}]\n");
  EXPECT_EQ(parse_error(valid), "");
  EXPECT_EQ(start_error(valid), "");

  std::string s = replace(valid, "coefficient: 10 W/m^2/K", "coefficient: -10 W/m^2/K");
  std::string e = parse_error(s);
  expect_contains(e, at(s, "-10 W/m^2/K"));
  expect_contains(e, "continuum.conditions[4].heat_transfer.coefficient: found '-10 W/m^2/K'");
  expect_contains(e, "expected a heat transfer coefficient >= 0");

  s = replace(valid, "coefficient: 10 W/m^2/K, temperature: 20", "coefficient: 10 W/m^2/K");
  expect_contains(parse_error(s), "heat_transfer.temperature: key is missing");

  s = replace(valid, "fluid_rate: 1e-6 m^2/s", "power: 10 W/m, fluid_rate: 1e-6 m^2/s");
  e = parse_error(s);
  expect_contains(e, at(s, "fluid_rate"));
  expect_contains(e, "found both power and fluid_rate; expected exactly one");

  s = replace(valid, ", fluid_rate: 1e-6 m^2/s", "");
  e = parse_error(s);
  expect_contains(e, at(s, "{name: well"));
  expect_contains(e, "found neither power nor fluid_rate; expected one of them");

  s = replace(valid, "fluid_rate: 1e-6 m^2/s", "fluid_rate: 1e-6 m^3/s");
  expect_contains(parse_error(s), at(s, "1e-6 m^3/s"));
}

// A field whose every unknown is prescribed (a one-cell column with its
// whole outline drained and held at a temperature) has no system to solve:
// every scheme runs, with the prescribed values (CHOLMOD crashed on the
// empty matrix).
TEST(continuum_bad_input, AFieldPrescribedEverywhereHasNoSystemToSolve) {
  for (const char* scheme : {"fixed_stress", "monolithic", "drained", "undrained"}) {
    std::string s = replace(kScene, "{boundary: top, pressure: 0}",
                            "{boundary: exterior, pressure: 0}\n    - {boundary: exterior, "
                            "temperature: 30}");
    s = replace(s, "  time_step: 100 s", std::string("  time_step: 100 s\n  scheme: ") + scheme);
    Scene scene = read_scene_text(s, "prescribed.yaml");
    scene.time.max_steps = 2;
    // The undrained split with the pressure held contracts by about
    // tau / (1 + tau) = 0.93 a pass here: 330 passes to 1e-10.
    continuum_controls(scene).max_iterations = 1000;
    const testing::RunResult run = testing::run_scene(scene, "continuum_prescribed");
    EXPECT_EQ(run.summary.status, "max_steps") << scheme;
  }
}

// A monitor outside the continuum's domain (fuzz case 220: it would write no
// values) is refused at its own line.
TEST(continuum_bad_input, AMonitorOutsideTheDomainIsLocated) {
  const std::string s = replace(kScene, "time: {end: 1000 s}\n",
                                "time: {end: 1000 s}\nmonitors: [{name: m, point: [5, 5]}]\n");
  const std::string e = start_error(s);
  expect_contains(e, at(s, "[5, 5]"));
  expect_contains(e, "outside the continuum's domain");
}

TEST(continuum_bad_input, AConditionOnAnUnknownBoundaryIsLocated) {
  const std::string s =
      replace(kScene, "{boundary: top, pressure: 0}", "{boundary: roof, pressure: 0}");
  expect_contains(parse_error(s), at(s, "roof"));
}

/// kScene with `permeability` as its material's permeability, written into
/// `dir` (beside the study files it names) and read.
Scene read_with_permeability(const std::string& dir, const std::string& permeability) {
  std::ofstream(dir + "/scene.yaml")
      << replace(kScene, "permeability: 1e-15 m^2", "permeability: " + permeability);
  return read_scene(dir + "/scene.yaml");
}

/// Each permeability of `cases` is refused with its message, located in the scene.
void expect_refused(const std::string& dir,
                    std::initializer_list<std::pair<std::string, std::string>> cases) {
  for (const auto& [permeability, expected] : cases) {
    try {
      read_with_permeability(dir, permeability);
      ADD_FAILURE() << permeability << " was accepted";
    } catch (const SceneError& e) {
      expect_contains(e.what(), expected);
      expect_contains(e.what(), "scene.yaml:");
    }
  }
}

// The far field's permeability from a REV study (issue 24, item 2): the
// mean tensor at the study's representative size, or at a named size; a
// study that found none, a missing file or a size it does not have are
// located errors.
TEST(continuum_bad_input, PermeabilityFromARevStudy) {
  const std::string dir = testing::scratch_dir("continuum_rev");
  auto write = [&](const std::string& name, const std::string& rev_size) {
    std::ofstream(dir + "/" + name)
        << R"({"rev_size": )" << rev_size
        << R"(, "sizes": [{"size": 4.0, "mean_k": {"xx": 2e-14, "yy": 5e-15, "xy": -1e-15}},
                           {"size": 8.0, "mean_k": {"xx": 3e-14, "yy": 1e-14, "xy": 2e-15}}]})";
  };
  write("reached.json", "8.0");
  write("not_reached.json", "null");
  EXPECT_EQ(continuum_controls(read_with_permeability(dir, "{rev: reached.json}"))
                .materials[0]
                .permeability,
            Eigen::Vector3d(3e-14, 1e-14, 2e-15));
  EXPECT_EQ(continuum_controls(read_with_permeability(dir, "{rev: not_reached.json, size: 4 m}"))
                .materials[0]
                .permeability,
            Eigen::Vector3d(2e-14, 5e-15, -1e-15));
  expect_refused(
      dir, {{"{rev: not_reached.json}", "found no representative size"},
            {"{rev: missing.json}", "found no file " + dir +
                                        "/missing.json (the path is relative to the scene file's "
                                        "folder); expected the rev.json that `fissure rev` writes"},
            {"{rev: reached.json, size: 5 m}", "found no size 5 m"}});
}

// A permeability that follows the stress (docs/continuum.md section 9): the
// law's parameters, a stress study's table, and a boundary value with a
// gradient; their mistakes are located errors.
TEST(continuum_bad_input, StressDependentPermeabilityAndGradients) {
  const std::string dir = testing::scratch_dir("continuum_stress_law");
  std::ofstream(dir + "/stress.json") << R"({"states": [
    {"state": 0, "effective_principal_MPa": {"sigma_1": 2.6, "sigma_3": 2.0},
     "largest_size": {"k_max": 1e-13, "k_min": 5e-14, "k_max_angle_deg": 0}},
    {"state": 1, "effective_principal_MPa": {"sigma_1": 13.0, "sigma_3": 10.0},
     "largest_size": {"k_max": 1e-14, "k_min": 4e-15, "k_max_angle_deg": 0}},
    {"state": 2, "effective_principal_MPa": {"sigma_1": 20.0, "sigma_3": 5.0},
     "largest_size": {"k_max": 0, "k_min": 0, "k_max_angle_deg": 0}}]})";
  // The magnitude series (the first state's ratio 1.3) makes the table.
  const Scene table = read_with_permeability(dir, "{stress_study: stress.json}");
  const auto& law = continuum_controls(table).materials[0].permeability_law;
  ASSERT_TRUE(law);
  EXPECT_EQ(law->stresses.size(), 2u);
  expect_refused(
      dir, {{"{stress_study: stress.json, states: [0, 2]}",
             "1 of the chosen stress states came to rest with a permeability tensor"},
            {"{stress_study: stress.json, states: [0, 5]}", "has no stress state 5"},
            {"{stress_study: nothing.json}", "found no file " + dir + "/nothing.json"},
            {"{stress_study: stress.json, k_max: 1e-13}",
             "permeability.k_max: found a key that has no effect here"},
            {"{law: exponential, k_max: 1e-14, k_min: 1e-13, coefficient: 0.1 1/MPa}",
             "found k_min 1e-13 m^2 above k_max 1e-14 m^2"},
            {"{law: exponential, k_max: 1e-14}", "permeability.coefficient: key is missing"},
            {"{law: exponential, k_max: 1e-14, coefficient: 0.1 MPa}", "permeability.coefficient"},
            {"{law: linear, k_max: 1e-14, coefficient: 0.1 1/MPa}", "permeability.law"}});
  std::string s = replace(kScene, "{boundary: top, pressure: 0}",
                          "{boundary: top, pressure: 0, gradient: [100 Pa/m, 0]}");
  EXPECT_EQ(parse_error(s), "");
  s = replace(kScene, "{boundary: top, traction: [0, -1 MPa]}",
              "{boundary: top, traction: [0, -1 MPa], gradient: [1, 0]}");
  expect_contains(parse_error(s), "found a gradient on a condition that is not a pressure");
  s = replace(kScene, "{boundary: top, pressure: 0}",
              "{boundary: top, pressure: 0, gradient: [1 K/m, 0]}");
  expect_contains(parse_error(s), at(s, "1 K/m"));
}

}  // namespace
}  // namespace fissure
