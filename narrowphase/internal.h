// The narrow phase module's interface to the rest of the library (not installed): the batched
// overlap tests over pairs given by reference, as the World holds its bodies, the table of pairs
// with the order in which kernels take their shapes, the mover's cast of one pair, and the overlap
// areas of shapes already checked.
#pragma once

#include "narrowphase/area/measures.h"
#include "narrowphase/batch/overlap_pairs.h"
#include "narrowphase/pairs.h"
#include "narrowphase/toi/mover_cast.h"
