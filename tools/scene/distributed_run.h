// `collide2d run` under mpirun (docs/distributed.md): the scene through a DistributedWorld, one
// slab per rank. Its summary counts what one process counts (the pairs, events, impacts and sensor
// contents, summed over the ranks), with the rank count; each frame's times are the slowest rank's.
#pragma once

#include "tools/scene/scene_run.h"

#include <mpi.h>

#include <iosfwd>

namespace collide2d::tool {

// Every rank runs the whole scene's kinematics and moves the bodies it owns; rank r adds the scene
// bodies whose index modulo the rank count is r, and every rank the chains. Throws SceneError for a
// body of several shapes, before any frame.
RunSummary run_distributed(Scene scene, MPI_Comm comm, unsigned threads, std::ostream* progress);

}  // namespace collide2d::tool
