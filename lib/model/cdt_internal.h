/*
 * What cdt.c and cdt_force.c share, private to them: growing arrays, the predicates, triangle
 * slots, and replacing a set of triangles (marked in c->cav, boundary in c->edge) by new ones
 * (c->fresh) linked to their neighbours.
 */
#ifndef BEZSURF_MODEL_CDT_INTERNAL_H
#define BEZSURF_MODEL_CDT_INTERNAL_H

#include "core/internal.h"
#include "model/cdt.h"

#define NEXT(i) (((i) + 1) % 3)
#define PREV(i) (((i) + 2) % 3)

int bsi_cdt_orient3(const bsi_cdt *c, uint32_t a, uint32_t b, uint32_t p);
long double bsi_cdt_incircle(const bsi_cdt *c, uint32_t a, uint32_t b, uint32_t d, const int64_t *p);
bs_status bsi_cdt_new_tri(bsi_cdt *c, uint32_t *id);
bs_status bsi_cdt_retire(bsi_cdt *c, uint32_t t);
int bsi_cdt_push_cav(bsi_cdt *c, uint32_t t);
void bsi_cdt_next_stamp(bsi_cdt *c);
int bsi_cdt_collect_boundary(bsi_cdt *c);
void bsi_cdt_link_fresh(bsi_cdt *c);
int bsi_cdt_slot_of(const bsi_cdt_tri *t, uint32_t v);

#endif
