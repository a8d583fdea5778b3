/*
 * shared.c - the one copy of the small helpers that internal.h and plane.h
 * declare in size builds (-Os), where each inlined copy would be a long
 * 64-bit sequence on a 32-bit core; speed builds inline them instead.
 */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
#define MOTE__DEFINE_SHARED 1
#endif
#include "internal.h"
#include "plane.h"

#if !MOTE__SHARED_COPY
typedef int mote__shared_unused;   /* ISO C wants a declaration */
#endif
