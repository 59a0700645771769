/* Z-buffer rasterizer: see raster.h. */
#include "raster.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void normalize3(double *a)
{
    double l = sqrt(dot3(a, a));
    if (l > 0.0)
        for (int k = 0; k < 3; k++)
            a[k] /= l;
}

/* Model coordinates to a z-up frame: a y-up model is turned by +90 degrees about x. */
static void to_zup(const raster *r, const double *p, double *q)
{
    if (r->up_y) {
        q[0] = p[0];
        q[1] = -p[2];
        q[2] = p[1];
    } else {
        memcpy(q, p, 3 * sizeof(double));
    }
}

/* The inverse of to_zup. */
static void from_zup(const raster *r, const double *q, double *p)
{
    if (r->up_y) {
        p[0] = q[0];
        p[1] = q[2];
        p[2] = -q[1];
    } else {
        memcpy(p, q, 3 * sizeof(double));
    }
}

/* Screen position (internal pixels, y down) and depth of a model point. */
static void project(const raster *r, const double *p, double *sx, double *sy, double *sz)
{
    double q[3], d[3];
    to_zup(r, p, q);
    for (int k = 0; k < 3; k++)
        d[k] = q[k] - r->center[k];
    *sx = r->ox + r->scale * dot3(d, r->right);
    *sy = r->oy - r->scale * dot3(d, r->up);
    *sz = dot3(d, r->back);
}

int raster_init(raster *r, size_t w, size_t h, size_t ss, double azimuth, double elevation, int up_y,
                const double lo[3], const double hi[3])
{
    memset(r, 0, sizeof(*r));
    r->w = w;
    r->h = h;
    r->ss = ss ? ss : 1;
    r->W = w * r->ss;
    r->H = h * r->ss;
    r->up_y = up_y;
    r->color = malloc(r->W * r->H * 3 * sizeof(float));
    r->depth = malloc(r->W * r->H * sizeof(float));
    if (r->color == NULL || r->depth == NULL) {
        raster_free(r);
        return -1;
    }
    /* Background: a soft vertical gradient. */
    for (size_t y = 0; y < r->H; y++) {
        float t = (float)y / (float)(r->H > 1 ? r->H - 1 : 1);
        for (size_t x = 0; x < r->W; x++) {
            float *c = r->color + 3 * (y * r->W + x);
            c[0] = 0.93f - 0.18f * t;
            c[1] = 0.94f - 0.17f * t;
            c[2] = 0.97f - 0.12f * t;
            r->depth[y * r->W + x] = -INFINITY;
        }
    }
    double a = azimuth * PI / 180.0, e = elevation * PI / 180.0;
    double back[3] = {cos(e) * cos(a), cos(e) * sin(a), sin(e)}, zup[3] = {0, 0, 1};
    double right[3] = {zup[1] * back[2] - zup[2] * back[1], zup[2] * back[0] - zup[0] * back[2],
                       zup[0] * back[1] - zup[1] * back[0]};
    if (dot3(right, right) < 1e-12) { /* looking straight down or up */
        right[0] = -sin(a);
        right[1] = cos(a);
        right[2] = 0.0;
    }
    normalize3(right);
    double up[3] = {back[1] * right[2] - back[2] * right[1], back[2] * right[0] - back[0] * right[2],
                    back[0] * right[1] - back[1] * right[0]};
    memcpy(r->back, back, sizeof back);
    memcpy(r->right, right, sizeof right);
    memcpy(r->up, up, sizeof up);
    double l[3], hh[3];
    to_zup(r, lo, l);
    to_zup(r, hi, hh);
    for (int k = 0; k < 3; k++)
        r->center[k] = 0.5 * (l[k] + hh[k]);
    /* Fit the projected corners of the box into 90% of the frame. */
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int c = 0; c < 8; c++) {
        double p[3] = {(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]}, q[3], d[3];
        to_zup(r, p, q);
        for (int k = 0; k < 3; k++)
            d[k] = q[k] - r->center[k];
        double x = dot3(d, right), y = dot3(d, up);
        xmin = fmin(xmin, x);
        xmax = fmax(xmax, x);
        ymin = fmin(ymin, y);
        ymax = fmax(ymax, y);
    }
    double sx = xmax > xmin ? 0.9 * (double)r->W / (xmax - xmin) : 1.0;
    double sy = ymax > ymin ? 0.9 * (double)r->H / (ymax - ymin) : 1.0;
    r->scale = fmin(sx, sy);
    r->box_w = xmax - xmin;
    r->reach = sqrt((hh[0] - l[0]) * (hh[0] - l[0]) + (hh[1] - l[1]) * (hh[1] - l[1]) + (hh[2] - l[2]) * (hh[2] - l[2]));
    if (!(r->reach > 0.0))
        r->reach = 1.0;
    r->ox = 0.5 * (double)r->W - r->scale * 0.5 * (xmin + xmax);
    r->oy = 0.5 * (double)r->H + r->scale * 0.5 * (ymin + ymax);
    /* A box too small (the scale overflows) or too large (its size overflows) cannot be framed. */
    if (!(isfinite(r->scale) && r->scale > 0.0 && isfinite(r->ox) && isfinite(r->oy))) {
        raster_free(r);
        return -2;
    }
    return 0;
}

static void shade(const raster *r, const double *n_model, const double *base, float *out)
{
    double n[3];
    to_zup(r, n_model, n);
    double nc[3] = {dot3(n, r->right), dot3(n, r->up), dot3(n, r->back)};
    normalize3(nc);
    if (nc[2] < 0.0) /* two-sided: light the side that faces the viewer */
        for (int k = 0; k < 3; k++)
            nc[k] = -nc[k];
    static const double L0[3] = {-0.45, 0.65, 0.62}, L1[3] = {0.7, -0.2, 0.5};
    double L[3] = {L0[0], L0[1], L0[2]}, F[3] = {L1[0], L1[1], L1[2]};
    normalize3(L);
    normalize3(F);
    double H[3] = {L[0], L[1], L[2] + 1.0};
    normalize3(H);
    double diff = fmax(0.0, dot3(nc, L)), fill = fmax(0.0, dot3(nc, F));
    double spec = pow(fmax(0.0, dot3(nc, H)), 48.0);
    for (int k = 0; k < 3; k++) {
        double c = base[k] * (0.16 + 0.72 * diff + 0.22 * fill) + 0.45 * spec;
        out[k] = (float)fmin(1.0, c);
    }
}

void raster_reserve_right(raster *r, size_t px)
{
    double left = (double)r->W - (double)(px * r->ss);
    if (!(left > 0.0))
        return;
    double cx = (0.5 * (double)r->W - r->ox) / r->scale, cy = (r->oy - 0.5 * (double)r->H) / r->scale;
    if (r->box_w > 0.0) /* as raster_init: 90% of the room in the tighter direction */
        r->scale = fmin(r->scale, 0.9 * left / r->box_w);
    r->ox = 0.5 * left - r->scale * cx;
    r->oy = 0.5 * (double)r->H + r->scale * cy;
}

void raster_put(raster *r, size_t x, size_t y, double depth, const double nrm[3], const double rgb[3])
{
    float *dz = r->depth + y * r->W + x;
    if (!(depth > *dz))
        return;
    *dz = (float)depth;
    shade(r, nrm, rgb, r->color + 3 * (y * r->W + x));
}

void raster_mesh(raster *r, const double *pos, const double *nrm, const double *vcol, const uint32_t *tri,
                 size_t ntri, const double rgb[3])
{
    for (size_t t = 0; t < ntri; t++) {
        double sx[3], sy[3], sz[3];
        const uint32_t *v = tri + 3 * t;
        int finite = 1;
        for (int k = 0; k < 3; k++) {
            project(r, pos + 3 * (size_t)v[k], &sx[k], &sy[k], &sz[k]);
            finite = finite && isfinite(sx[k]) && isfinite(sy[k]) && isfinite(sz[k]);
        }
        double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
        /* NaN or Inf would pass the bounds tests below and make the pixel loops unbounded */
        if (!finite || !isfinite(area) || fabs(area) < 1e-12)
            continue;
        double x0 = floor(fmin(sx[0], fmin(sx[1], sx[2]))), x1 = ceil(fmax(sx[0], fmax(sx[1], sx[2])));
        double y0 = floor(fmin(sy[0], fmin(sy[1], sy[2]))), y1 = ceil(fmax(sy[0], fmax(sy[1], sy[2])));
        if (x1 < 0 || y1 < 0 || x0 >= (double)r->W || y0 >= (double)r->H)
            continue;
        size_t xa = x0 < 0 ? 0 : (size_t)x0, ya = y0 < 0 ? 0 : (size_t)y0;
        size_t xb = x1 >= (double)r->W ? r->W - 1 : (size_t)x1, yb = y1 >= (double)r->H ? r->H - 1 : (size_t)y1;
        for (size_t y = ya; y <= yb; y++)
            for (size_t x = xa; x <= xb; x++) {
                double px = (double)x + 0.5, py = (double)y + 0.5;
                double w0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
                double w1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
                double w2 = 1.0 - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0)
                    continue;
                double z = w0 * sz[0] + w1 * sz[1] + w2 * sz[2];
                if (!(z > r->depth[y * r->W + x]))
                    continue;
                double n[3], c[3];
                for (int k = 0; k < 3; k++) {
                    n[k] = w0 * nrm[3 * (size_t)v[0] + (size_t)k] + w1 * nrm[3 * (size_t)v[1] + (size_t)k] +
                           w2 * nrm[3 * (size_t)v[2] + (size_t)k];
                    c[k] = vcol ? w0 * vcol[3 * (size_t)v[0] + (size_t)k] + w1 * vcol[3 * (size_t)v[1] + (size_t)k] +
                                      w2 * vcol[3 * (size_t)v[2] + (size_t)k]
                                : rgb[k];
                }
                raster_put(r, x, y, z, n, c);
            }
    }
}

void raster_ray(const raster *r, size_t x, size_t y, double org[3], double dir[3])
{
    double cx = ((double)x + 0.5 - r->ox) / r->scale, cy = (r->oy - ((double)y + 0.5)) / r->scale;
    double q[3], d[3];
    for (int k = 0; k < 3; k++) {
        q[k] = r->center[k] + cx * r->right[k] + cy * r->up[k] + r->reach * r->back[k];
        d[k] = -r->back[k];
    }
    from_zup(r, q, org);
    from_zup(r, d, dir);
}

/* Narrow [t0, t1] to the parameters where a + t (b - a) lies in [lo, hi]; 0 if none does. */
static int clip(double a, double b, double lo, double hi, double *t0, double *t1)
{
    double d = b - a;
    if (d == 0.0)
        return a >= lo && a <= hi;
    double ta = (lo - a) / d, tb = (hi - a) / d;
    if (ta > tb) {
        double t = ta;
        ta = tb;
        tb = t;
    }
    *t0 = fmax(*t0, ta);
    *t1 = fmin(*t1, tb);
    return *t0 <= *t1;
}

void raster_line(raster *r, const double a[3], const double b[3], double width, const double rgb[3])
{
    double ax, ay, az, bx, by, bz;
    project(r, a, &ax, &ay, &az);
    project(r, b, &bx, &by, &bz);
    double half = 0.5 * width * (double)r->ss;
    if (!(isfinite(ax) && isfinite(ay) && isfinite(az) && isfinite(bx) && isfinite(by) && isfinite(bz)))
        return;
    /* Only the part inside the frame (widened by the line's half width) is drawn, so the number of
     * steps is bounded by the frame's size whatever the end points. */
    double t0 = 0.0, t1 = 1.0;
    if (!clip(ax, bx, -half - 1.0, (double)r->W + half + 1.0, &t0, &t1) ||
        !clip(ay, by, -half - 1.0, (double)r->H + half + 1.0, &t0, &t1))
        return;
    double dx0 = bx - ax, dy0 = by - ay, dz0 = bz - az;
    bx = ax + t1 * dx0, by = ay + t1 * dy0, bz = az + t1 * dz0;
    ax += t0 * dx0, ay += t0 * dy0, az += t0 * dz0;
    double len = hypot(bx - ax, by - ay);
    size_t steps = (size_t)ceil(len) + 1;
    double bias = 0.004 * (double)r->W / r->scale; /* 0.4% of the frame, in model units */
    for (size_t s = 0; s <= steps; s++) {
        double t = (double)s / (double)steps;
        double x = ax + t * (bx - ax), y = ay + t * (by - ay), z = az + t * (bz - az);
        for (double dy = -half; dy <= half; dy += 1.0)
            for (double dx = -half; dx <= half; dx += 1.0) {
                double px = floor(x + dx), py = floor(y + dy);
                if (px < 0 || py < 0 || px >= (double)r->W || py >= (double)r->H)
                    continue;
                size_t i = (size_t)py * r->W + (size_t)px;
                if (z + bias < r->depth[i])
                    continue;
                for (int k = 0; k < 3; k++)
                    r->color[3 * i + (size_t)k] = (float)rgb[k];
            }
    }
}

unsigned char raster_to_byte(double c)
{
    return (unsigned char)lround(255.0 * pow(fmin(1.0, fmax(0.0, c)), 1.0 / 1.1));
}

void raster_finish(const raster *r, unsigned char *rgb)
{
    double norm = 1.0 / (double)(r->ss * r->ss);
    for (size_t y = 0; y < r->h; y++)
        for (size_t x = 0; x < r->w; x++)
            for (int k = 0; k < 3; k++) {
                double acc = 0.0;
                for (size_t j = 0; j < r->ss; j++)
                    for (size_t i = 0; i < r->ss; i++)
                        acc += r->color[3 * ((y * r->ss + j) * r->W + x * r->ss + i) + (size_t)k];
                rgb[3 * (y * r->w + x) + (size_t)k] = raster_to_byte(acc * norm);
            }
}

void raster_free(raster *r)
{
    free(r->color);
    free(r->depth);
    r->color = NULL;
    r->depth = NULL;
}
