/* A small z-buffer rasterizer for the `render` command: orthographic view from an azimuth and an
 * elevation, per-pixel interpolated normals, two-sided Lambert + Phong (Blinn) shading, lines drawn
 * over the surface with the same depth test, and supersampling for smooth edges. */
#ifndef BEZSURF_TOOLS_RASTER_H
#define BEZSURF_TOOLS_RASTER_H

#include <stddef.h>
#include <stdint.h>

typedef struct raster {
    size_t w, h, ss;            /* output size and supersampling factor */
    size_t W, H;                /* internal size, w*ss x h*ss */
    float *color;               /* W*H*3, linear 0..1 */
    float *depth;               /* W*H, larger is nearer */
    double right[3], up[3], back[3], center[3];
    double scale, ox, oy;       /* screen = scale * (camera x, y) + offset */
    double box_w;               /* width of the framed box seen by the camera (camera units) */
    double reach;               /* the box's diagonal: rays start this far in front of its centre */
    int up_y;                   /* the model's up axis is y (else z) */
} raster;

/* Set up the image and a camera looking at the box lo..hi (model coordinates) from the given
 * azimuth and elevation in degrees, fitted to the frame. 0 on success, -1 if out of memory, -2 if
 * the box cannot be framed (its size or the scale fitting it to the frame is not a finite number). */
int raster_init(raster *r, size_t w, size_t h, size_t ss, double azimuth, double elevation, int up_y,
                const double lo[3], const double hi[3]);

/* Fit the camera again into the frame less a strip of px output pixels on the right (kept for a
 * legend): the same view, smaller and centred in what is left. */
void raster_reserve_right(raster *r, size_t px);

/* Draw triangles (packed positions and unit normals, 3 indices each) in a base colour (0..1), or,
 * when vcol is not NULL, in colours given per vertex (3 packed, 0..1) and interpolated. */
void raster_mesh(raster *r, const double *pos, const double *nrm, const double *vcol, const uint32_t *tri,
                 size_t ntri, const double rgb[3]);

/* The ray through the centre of internal pixel (x, y), in model coordinates: it starts in front of
 * the framed box and its direction is a unit vector, so a point at ray parameter t has the depth
 * r->reach - t (the depth raster_mesh gives it). */
void raster_ray(const raster *r, size_t x, size_t y, double org[3], double dir[3]);

/* Shade internal pixel (x, y) as a surface point at the given depth with normal nrm (model
 * coordinates) and colour rgb, unless something nearer is there already. */
void raster_put(raster *r, size_t x, size_t y, double depth, const double nrm[3], const double rgb[3]);

/* Draw a 3-D line segment of the given width (output pixels) and colour; depth-tested against the
 * surface with a small bias so lines on it stay visible. */
void raster_line(raster *r, const double a[3], const double b[3], double width, const double rgb[3]);

/* A linear colour component (0..1, clamped) as the 8-bit value of the output (a gamma of 1.1). */
unsigned char raster_to_byte(double c);

/* Resolve to 8-bit sRGB-ish output, w*h*3 bytes. */
void raster_finish(const raster *r, unsigned char *rgb);

void raster_free(raster *r);

#endif
