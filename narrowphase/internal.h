// The narrow phase module's interface to the rest of the library (not installed): the batched
// overlap tests over pairs given by reference, as the World holds its bodies, and the table of pairs
// with the order in which kernels take their shapes.
#pragma once

#include "narrowphase/batch/overlap_pairs.h"
#include "narrowphase/pairs.h"
