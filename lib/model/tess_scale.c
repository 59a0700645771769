/*
 * Tessellation: the metric of each face (tess.h). Native (u, v) times the face's mean |S_u| and
 * |S_v| make lengths; the flatter direction is then stretched (by at most ANISOTROPY) in the
 * ratio of the chord lengths the two directions' curvatures allow, so that the triangles the
 * Delaunay refinement makes, equilateral in the metric, are long along rulings.
 */
#include "model/tess.h"

#include <math.h>
#include <stdlib.h>

#define SCALE_GRID 5
#define ANISOTROPY 8.0

/* Normal curvature along u and v at (u, v) from the second differences of the face's points
 * (step h of the box), into k[2]; 0 where it cannot be told. */
static void curvatures(const bs_model *m, size_t f, double u, double v, double hu, double hv, double *k)
{
    double p[3], a[3], b[3], c[3], d[3], pu[3], pv[3];
    k[0] = k[1] = 0.0;
    if (!bsi_face_partials(m, f, u, v, p, pu, pv) || !bsi_face_point(m, f, u - hu, v, a) ||
        !bsi_face_point(m, f, u + hu, v, b) || !bsi_face_point(m, f, u, v - hv, c) || !bsi_face_point(m, f, u, v + hv, d))
        return;
    double n[3];
    bsi_cross3(pu, pv, n);
    double ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double lu2 = pu[0] * pu[0] + pu[1] * pu[1] + pu[2] * pu[2], lv2 = pv[0] * pv[0] + pv[1] * pv[1] + pv[2] * pv[2];
    if (!(ln > 0.0) || !(lu2 > 0.0) || !(lv2 > 0.0))
        return;
    double suu = 0.0, svv = 0.0;
    for (int q = 0; q < 3; q++) {
        suu += (a[q] - 2.0 * p[q] + b[q]) / (hu * hu) * n[q] / ln;
        svv += (c[q] - 2.0 * p[q] + d[q]) / (hv * hv) * n[q] / ln;
    }
    k[0] = fabs(suu) / lu2;
    k[1] = fabs(svv) / lv2;
}

bs_status bsi_tm_scales(tm_job *j)
{
    const bs_model *m = j->m;
    j->scale = calloc(m->nface ? m->nface : 1, sizeof(tm_face_scale));
    if (j->scale == NULL)
        return BS_ERR_NO_MEMORY;
    for (size_t f = 0; f < m->nface; f++) {
        const bsi_face *face = &m->faces[f];
        double su = 0.0, sv = 0.0, ku = 0.0, kv = 0.0;
        double wu = face->box[1] - face->box[0], wv = face->box[3] - face->box[2];
        for (int a = 0; a < SCALE_GRID; a++)
            for (int b = 0; b < SCALE_GRID; b++) {
                double u = face->box[0] + wu * (a + 0.5) / SCALE_GRID;
                double v = face->box[2] + wv * (b + 0.5) / SCALE_GRID;
                double p[3], pu[3], pv[3], k[2];
                if (bsi_face_partials(m, f, u, v, p, pu, pv)) {
                    su += sqrt(pu[0] * pu[0] + pu[1] * pu[1] + pu[2] * pu[2]);
                    sv += sqrt(pv[0] * pv[0] + pv[1] * pv[1] + pv[2] * pv[2]);
                }
                curvatures(m, f, u, v, 0.25 * wu / SCALE_GRID, 0.25 * wv / SCALE_GRID, k);
                ku = k[0] > ku ? k[0] : ku;
                kv = k[1] > kv ? k[1] : kv;
            }
        if (!(su > 0.0) || !isfinite(su))
            su = sv > 0.0 && isfinite(sv) ? sv : 1.0;
        if (!(sv > 0.0) || !isfinite(sv))
            sv = su;
        su /= SCALE_GRID * SCALE_GRID;
        sv /= SCALE_GRID * SCALE_GRID;
        /* Stretch the flatter direction: the sizes a chord may have along u and v go as
         * 1 / sqrt(curvature), and triangles equilateral in the metric are then longer along the
         * flat direction (a cylinder's rulings), at most ANISOTROPY times. */
        double ratio = 1.0;
        if (ku > 0.0 || kv > 0.0)
            ratio = kv > 0.0 ? sqrt(ku / kv) : ANISOTROPY; /* size along v over size along u */
        ratio = ratio > ANISOTROPY ? ANISOTROPY : ratio < 1.0 / ANISOTROPY ? 1.0 / ANISOTROPY : ratio;
        if (!isfinite(ratio))
            ratio = 1.0;
        j->scale[f].su = ratio < 1.0 ? su * ratio : su;
        j->scale[f].sv = ratio > 1.0 ? sv / ratio : sv;
    }
    return BS_OK;
}

