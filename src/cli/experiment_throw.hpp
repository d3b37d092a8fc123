#pragma once
// `termpool experiment throw`: how far a cut throws the object ball off the line of centres.

#include <termpool/params.hpp>

namespace termpool::cli {

/// The throw angle, degrees, that the simulator gives a cut of `cut_deg` degrees when the cue
/// ball arrives at `speed` m/s, stunned (no spin) or rolling; positive when the object ball is
/// thrown towards the cue ball's line, as cut-induced throw is.
double measured_throw_deg(const PhysicsParams& params, double speed, double cut_deg, bool rolling);

/// Prints the throw against the cut angle at several speeds, stun and rolling, for the
/// ball-ball friction `model` (its default constants): a table and a chart per cue-ball state,
/// or CSV. Returns the exit status.
int throw_study(BallFrictionModel model, bool csv);

} // namespace termpool::cli
