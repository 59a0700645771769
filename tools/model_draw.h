/* Models in `bezsurf render`: each face drawn only inside its trim loops, for display (a grid of
 * each patch classified with bs_model_classify, the triangles crossing the boundary clipped at
 * it), optionally coloured by surface kind with the faces' boundaries drawn dark and a legend. */
#ifndef BEZSURF_TOOLS_MODEL_DRAW_H
#define BEZSURF_TOOLS_MODEL_DRAW_H

#include "raster.h"
#include "cmds.h"

typedef struct model_draw {
    bs_model *model; /* NULL: the input is not a model file (STEP, IGES, OBJ) */
    int faces;       /* colour by surface kind, boundaries and legend (--faces) */
    unsigned kinds;  /* bit k: a face of kind k was drawn */
} model_draw;

/* The input as a model when it is a STEP, IGES or OBJ file with trimmed faces (md->model stays
 * NULL for anything else), or with faces whatever it is. CLI_OK or the exit code after a
 * message. */
int model_draw_open(const char *cmd, const cli_input *in, int faces, model_draw *md);
void model_draw_close(model_draw *md);

/* The colour of a face of kind BS_FACE_* in --faces pictures. */
void model_draw_kind_color(int kind, double rgb[3]);

/* Draw the model's trimmed faces into r (framed for the model's coordinates times unit): in rgb,
 * or by kind with md->faces. About one triangle per two pixels of the picture (from 20000 to
 * 300000), budget at most (0: no budget); with wire, instead, the model's watertight mesh within
 * rel of its size (bs_model_tessellate) with its triangles' edges. *ntri receives the count
 * drawn. CLI_OK or the exit code after a message. */
int model_draw_faces(model_draw *md, raster *r, double unit, const double rgb[3], int wire, double rel,
                     size_t budget, size_t *ntri);

/* Width of the legend strip on the right of a w x h picture (0 without --faces or when too
 * small), and the legend itself: one swatch and name per kind drawn. */
size_t model_draw_legend_strip(const model_draw *md, size_t w, size_t h);
void model_draw_legend(const model_draw *md, unsigned char *rgb, size_t w, size_t h);

#endif
