// The poro-thermo-elastic continuum as a Fissure process (theory.md 5,
// docs/continuum.md): a saturated, linear thermo-poro-elastic domain meshed
// with Taylor-Hood triangles, advanced by backward Euler with the scene's
// scheme (poroelastic_solver.h). It owns its fields (u, p, T on its mesh)
// and runs alone or beside the block processes. Its interfaces (conditions
// `interface`, docs/continuum.md 4) are boundaries another process loads
// through the shared field continuum_interfaces (tractions, pressures,
// temperatures in; displacements and fluxes out).
#pragma once

#include <optional>

#include "continuum/poroelasticity/continuum_constraints.h"
#include "continuum/poroelasticity/continuum_mesh.h"
#include "continuum/poroelasticity/continuum_settings.h"
#include "continuum/poroelasticity/poroelastic_matrices.h"
#include "continuum/poroelasticity/poroelastic_solver.h"
#include "core/io/monitor_source.h"
#include "core/io/results_part.h"
#include "core/process/process.h"
#include "rockmass/fields/continuum_interface.h"

namespace fissure::continuum {

class ContinuumProcess;

/// The fields at a point: displacement, pressure, temperature, total stress
/// (tension +) and Darcy flux.
struct PointValues {
  Vec2 displacement = Vec2::Zero();
  double pressure = 0, temperature = 0;
  /// sxx, syy, sxy, szz (plane strain: out of plane; axisymmetric: hoop)
  Eigen::Vector4d stress = Eigen::Vector4d::Zero();
  Vec2 darcy_flux = Vec2::Zero();  ///< m/s
};

/// m.ux, m.uy, m.p, m.T (with heat), m.sxx, m.syy, m.sxy, m.szz, m.qx, m.qy at the
/// monitors (fixed in space).
class ContinuumMonitors final : public MonitorSource {
 public:
  explicit ContinuumMonitors(const ContinuumProcess& process) : process_(process) {}
  std::vector<MonitorColumn> columns() const override;
  void values(const RockMass& state, int point, std::span<double> out) const override;
  std::string why_missing(const RockMass& state, int point, std::string_view column) const override;

 private:
  const ContinuumProcess& process_;
};

/// The "continuum" grid of results.h5 / results.xdmf: the triangles'
/// vertices once in /mesh (and the sources, as markers), per frame the
/// displacement, pressure, excess pressure, temperature and temperature
/// change at the vertices and the stress components and Darcy flux per
/// triangle (at its centroid).
class ContinuumResults final : public ResultsPart {
 public:
  explicit ContinuumResults(const ContinuumProcess& process) : process_(process) {}
  void write_mesh(FrameWriter& frame, const RockMass& state) override;
  std::size_t frame_bytes(const RockMass& state) const override;
  void write_frame(FrameWriter& frame, const RockMass& state) override;

 private:
  const ContinuumProcess& process_;
};

class ContinuumProcess final : public Process {
 public:
  explicit ContinuumProcess(const Scene& scene);

  std::string name() const override { return "continuum"; }
  std::vector<std::string> reads() const override { return reads_; }
  std::vector<std::string> writes() const override { return writes_; }
  void initialize(RockMass& state) override;
  double proposed_dt(const RockMass& state) const override;
  StepReport advance(RockMass& state, double t, double dt) override;
  /// The interfaces' returned values (displacements, fluid and heat fluxes
  /// per node), for the iterated coupling scheme.
  std::vector<ExchangedField> exchanged_values(const RockMass& state) const override;
  void set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) override;
  const MonitorSource* monitors() const override { return &monitors_; }
  ResultsPart* results() override { return &results_; }
  nlohmann::json statistics() const override;
  nlohmann::json energy(const RockMass& /*state*/) const override { return {}; }
  void save(CheckpointWriter& out, const RockMass& state) const override;
  void restore(CheckpointReader& in, RockMass& state) override;

  const ContinuumControls& controls() const { return c_; }
  const ContinuumMesh& mesh() const { return mesh_; }
  const PoroState& fields() const { return fields_; }
  /// The solver (its reactions after a step; tests).
  const PoroelasticSolver& solver() const { return *solver_; }
  /// Per triangle, its permeability (kxx, kyy, kxy) now and at the start
  /// (they differ where a material's permeability follows the stress).
  const std::vector<Eigen::Vector3d>& permeability() const { return matrices_.permeability; }
  const std::vector<Eigen::Vector3d>& initial_permeability() const { return initial_permeability_; }
  /// The fields in triangle `t` at barycentric point `w`.
  PointValues values_in(int t, const Eigen::Vector3d& w) const;
  /// The monitor's place in the mesh; triangle -1 when outside the domain.
  const ContinuumMesh::Place& monitor_place(int point) const { return monitor_places_[point]; }
  bool has_monitor_place(int point) const {
    return point >= 0 && point < static_cast<int>(monitor_places_.size());
  }

 private:
  /// What save() writes (Self const) and restore() reads (core/io/checkpoint.h).
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a);
  /// Interfaces: the given values into the solver's loads and prescribed
  /// values; the returned values into the shared field.
  void take_interface_values(RockMass& state);
  void give_interface_values(RockMass& state) const;
  /// One step of the solver from fields_ into `next`; with a
  /// stress-dependent permeability, passes until the tensors settle.
  StepStatistics step_fields(PoroState& next, double t, double dt);
  /// Visits every returned value of the interfaces in the state, in a fixed order.
  template <class State, class Visit>
  void for_each_returned(State& state, Visit&& visit) const;

  /// A condition `interface` on the mesh.
  struct Interface {
    int condition = -1;               ///< index in c_.conditions
    std::vector<int> vertices;        ///< the field's nodes
    std::vector<double> measure;      ///< int N_a W ds per node
    std::vector<BoundaryEdge> edges;  ///< in the published order
    /// The places of the other side's fluid inflow points, kept while its
    /// points stay the same.
    struct Placed {
      std::vector<Vec2> points;
      std::vector<InterfacePlace> places;
    };
    Placed fluid;
  };
  std::vector<Interface> interfaces_;
  /// Adds to `f` the traction of the initial stress on interface i,
  /// sigma_0(x) n: what an interface that takes tractions carries while the
  /// other side gives none (at the start, before the blocks give theirs).
  void add_initial_traction(const Interface& i, Eigen::VectorXd& f) const;
  /// The interface as published: its nodes, edges, what it takes and the
  /// continuum's impedance there; sets i.edges.
  ContinuumInterface published_interface(Interface& i) const;
  /// The places of points given on an interface (kept in `cache` while the
  /// points stay), checked: taken by the condition (`key`), one value per
  /// point, each on the interface.
  template <class T>
  const std::vector<InterfacePlace>& place_points(Interface::Placed& cache,
                                                  const ContinuumInterface& published,
                                                  const ContinuumCondition& k,
                                                  const InterfacePointLoads<T>& given, bool taken,
                                                  const char* what, const char* key);
  /// With interfaces: continuum_interface_loads / continuum_interfaces.
  std::vector<std::string> reads_, writes_;
  ContinuumControls c_;
  std::vector<Monitor> monitors_in_scene_;
  bool with_blocks_ = false;  ///< the scene has blocks (monitors may watch them)
  Vec2 gravity_ = Vec2::Zero();
  ContinuumMesh mesh_;
  std::vector<char> owned_;  ///< the triangles this rank assembles
  PoroelasticMatrices matrices_;
  std::vector<Eigen::Vector3d> initial_permeability_;  ///< per triangle, at the initial state
  ContinuumConstraints constraints_;
  std::optional<PoroelasticSolver> solver_;
  PoroState fields_;
  PoroState previous_;      ///< the fields one step back (BDF2)
  double previous_dt_ = 0;  ///< s; 0: no step yet
  std::vector<ContinuumMesh::Place> monitor_places_;

  struct Counters {
    long steps = 0, passes = 0, most_passes = 0;
    /// Of a stress-dependent permeability: its passes, the most in a step.
    long permeability_passes = 0, most_permeability_passes = 0;
    double largest_last_change = 0;
    double mesh_seconds = 0, assembly_seconds = 0, step_seconds = 0;
  } counters_;
  ContinuumMonitors monitors_{*this};
  ContinuumResults results_{*this};
};

}  // namespace fissure::continuum
