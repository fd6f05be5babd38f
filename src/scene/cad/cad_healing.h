// cad_healing.h - Open CASCADE's shape healing after a STEP translation, switched and timed.
// The STEP reader runs the operators its resource file names for the sequence "FromSTEP"
// (ShapeFix, FixShape), inside its transfer; idview names its own operator there instead,
// which runs FixShape as the resource file configures it (or nothing, healing off) and adds up
// the time it took. Process-wide, as Open CASCADE's resource is: for the process that reads,
// one file at a time (a worker, or a load in process). Internal; speaks Open CASCADE.
#pragma once

namespace scene::cad {

// Heal (the default) or not, for the STEP reads that follow in this process.
void setStepHealing(bool on);

// Milliseconds spent healing since the last call, and back to 0.
double takeHealingMs();

} // namespace scene::cad
