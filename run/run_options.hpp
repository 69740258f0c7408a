#pragma once
// Run parameters of lmgc-solve, named like the parameters of LMGC90's command.py scripts.
#include <limits>
#include <optional>
#include <string>

#include "run/nlgs_options.hpp"

namespace lmgc::run {

struct RunOptions {
  double dt = 1e-3;                  // time step [s]
  double theta = 0.5;                // θ of the Moreau–Jean scheme
  long steps = 1000;                 // number of steps
  NlgsOptions nlgs;                  // solver type, norm, tol, relax, gs_it1, gs_it2
  double rloc_tol = 0.0;             // warm-start matching tolerance (RecupRloc(tol)); 0 = by contactors
  long write_every = 0;              // DOF/Vloc_Rloc .OUT.n every this many steps (0 = never)
  long display_every = 0;            // DISPLAY files every this many steps (0 = never)
  bool quiet = false;                // no progress line
  bool strict = false;               // exit 3 when a step did not converge within gs_it1 × gs_it2
  bool new_rotation_scheme = false;  // RBDY3: Cayley frame update (RBDY3_NewRotationScheme)
  int cundall_iterations = 100;      // PRPRx: cap of Cundall's common-plane search (CUNDALL ITERATION)
  // FATAL DAMPING (or INI V DOF NULL) before the first step: every body starts at rest.
  bool zero_initial_velocity = false;
  // Bounds of LMGC90's RBDY2 "out of bounds" (SetYminBoundary, ...).
  double y_min = -std::numeric_limits<double>::infinity();
  double y_max = std::numeric_limits<double>::infinity();
  double x_min = -std::numeric_limits<double>::infinity();
  double x_max = std::numeric_limits<double>::infinity();
  double x_period = 0.0;              // SetPeriodicCondition(xperiod)
  double y_period = 0.0;              // SetPeriodicCondition(xperiod, yperiod), 3D
  bool ptpt3_network = false;         // PTPT3 links from DATBOX/PTPT3_NETWORK.DAT (PTPT3_LoadNetwork)
  bool ptpt3_current_nonuc0 = false;  // PTPT3_UseCurrentNonuc0(1): lengths from the file / the start
  // RBDY3_SetSourcePointWithIni(first, radius, x, y, z): bodies after `first` (1-based) enter one by
  // one at the point; first = 0 means none.
  long source_first = 0;
  double source_radius = 0.0;
  double source_point[3] = {0.0, 0.0, 0.0};
  // RBDY3_SetSourcePointWithIni (true): the point is a position, the waiting bodies' references are
  // zeroed; RBDY3_SetSourcePoint (false): a translation from each body's own reference.
  bool source_point_absolute = true;
};

// Parses LMGC90's spellings: 'Quad ', 'QuaN ', 'Maxm ', 'QM/16' and 'Stored_Delassus_Loops',
// 'Exchange_Local_Global' (trailing blanks ignored). False when unknown.
bool parse_norm(const std::string& text, NlgsNorm& norm);
bool parse_storage(const std::string& text, NlgsStorage& storage);

}  // namespace lmgc::run
