#include "capsula/run/SummaryJson.hpp"

namespace capsula::run {

io::JsonValue sampleJson(const CellSample& s, bool wall)
{
  io::JsonValue v = io::JsonValue::object();
  const auto& d = s.shape.deformation;
  v["D12"] = d.D12;
  v["D13"] = d.D13;
  v["D23"] = d.D23;
  v["inclination (degrees)"] = d.inclinationDegrees;
  v["centroid"] = io::JsonValue::array({s.shape.centroid[0], s.shape.centroid[1], s.shape.centroid[2]});
  v["u_slip"] = s.slipVelocity();
  v["u_migr"] = s.migrationVelocity();
  v["u_slip (spline of outputs)"] = s.splineSlipVelocity();
  v["u_migr (spline of outputs)"] = s.splineMigrationVelocity();
  v["u_lift (before the fixed-height constraint)"] = s.unconstrainedVelocity[1];
  v["rotation rate"] = io::JsonValue::array({s.rotation[0], s.rotation[1], s.rotation[2]});
  v["volume"] = s.shape.volume;
  v["area"] = s.shape.area;
  v["volume change"] = s.volumeChange;
  v["area change"] = s.areaChange;
  v["reduced volume"] = s.shape.reducedVolume;
  v["footprint A_xz"] = s.shape.footprintXZ;
  v["mean shear stress"] = s.stress.mean;
  v["max shear stress"] = s.stress.maximum;
  v["mean shear stress increase"] = s.meanStressIncrease;
  v["max shear stress increase"] = s.maximumStressIncrease;
  v["shape change rate"] = s.shapeChangeRate;
  v["minimum angle (degrees)"] = s.stability.minAngleDegrees;
  v["maximum edge ratio"] = s.stability.maxEdgeRatio;
  v["maximum element distortion"] = s.stability.maxDistortion;
  v["most compressive tension"] = s.stability.mostCompressiveTension;
  v["least principal stiffness / G"] = s.stability.minPrincipalStiffness;
  if (wall) { // measured from the plane y = 0, meaningless without the wall
    v["wall gap per element size"] = s.stability.wallGapPerElementSize;
  }
  if (s.adhesion) {
    const adhesion::AdhesionSummary& a = *s.adhesion;
    v["bonds"] = a.bonds;
    v["bond force"] = io::JsonValue::array({a.bondForce[0], a.bondForce[1], a.bondForce[2]});
    v["contact area"] = a.contactArea;
    v["minimum gap"] = a.minimumGap;
  }
  if (s.tether) {
    const adhesion::TetherState& t = s.tether->state;
    v["tether force"] = io::JsonValue::array({t.force[0], t.force[1], t.force[2]});
    v["tether attachment"] = io::JsonValue::array({t.attachment[0], t.attachment[1], t.attachment[2]});
    v["tether length"] = t.length;
    v["tether angle to the wall (degrees)"] = t.inclinationDegrees;
    v["pivot angle (degrees)"] = s.tether->pivotAngleDegrees;
  }
  return v;
}

io::JsonValue pairJson(const PairSample& p)
{
  io::JsonValue v = io::JsonValue::object();
  v["separation"] = io::JsonValue::array({p.separation[0], p.separation[1], p.separation[2]});
  v["distance"] = p.distance;
  v["relative velocity"] = io::JsonValue::array({p.relativeVelocity[0], p.relativeVelocity[1], p.relativeVelocity[2]});
  v["relative u_slip"] = p.relativeSlip;
  v["gap"] = p.gap.distance;
  v["gap per element size"] = p.gapPerElementSize;
  return v;
}

} // namespace capsula::run
