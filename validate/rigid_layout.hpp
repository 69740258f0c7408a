#pragma once
// Where the rigid contactors of a case are at the start: BODIES.DAT's node coordinates plus the
// DOF.INI displacement of each body, and the contactor's own offset and frame. Shared by the
// interpenetration and time-step checks. 2D bodies turn by coo3 + X(3); RBDY3 bodies by the frame
// a, b, c of DOF.INI (contactor offsets and frames are taken as given in that body frame).
// docs/lmgc90-facts/datbox-inputs.md §1.2-1.4 (contactors), §6 (DOF.INI).
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "case_folder/case_files.hpp"
#include "grammar/bodies/ast.hpp"

namespace lmgc::validate {

using case_folder::CaseFiles;  // the checks read the case as loaded (case_folder/)

enum class RigidShape {
  disk,     // DISKx, DISKb: centre, radius
  sphere,   // SPHER, SPHEb: centre, radius
  stadium,  // JONCx: segment of half length half.x along axes.col(0), thickened by half.y
  box,      // PLANx: half lengths half along the columns of axes
  polygon,  // POLYG: only its bounding box is used
};

struct PlacedContactor {
  const grammar::Body* body = nullptr;
  std::size_t rank = 0;        // rank of the body within its type
  std::size_t body_index = 0;  // index of the body in BodiesFile::bodies (same body: same index)
  const grammar::Contactor* contactor = nullptr;
  std::string see_class;  // "RBDY2/DISKx/BLEUx"
  RigidShape shape = RigidShape::disk;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  double radius = 0.0;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  // bounding box
  bool translation_driven = false;  // DRV_DOF.DAT drives a translation velocity of the body
};

struct RigidLayout {
  int dimension = 2;
  std::vector<PlacedContactor> contactors;  // bodies in file order, contactors in body order
};

RigidLayout place_rigid_contactors(const CaseFiles& files);

// Penetration depth of two placed contactors (> 0: they overlap by that much), for the pairs
// disk-disk, disk-stadium, sphere-sphere and sphere-box; nullopt-like NaN for other pairs.
double penetration(const PlacedContactor& a, const PlacedContactor& b);

}  // namespace lmgc::validate
