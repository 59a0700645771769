/* Writing surfaces as OBJ free-form text: one `cstype [rat] bezier` surface per patch, its control
 * vertices first; numbers as in the .bpt writer (shortest exact decimals, '.' in every locale). */
#include "io/internal.h"
#include "mesh/sink.h"


#define REFS_PER_LINE 16 /* control vertices per line of a surf statement, then a continuation */

static void put_double(bsi_sink *o, double x)
{
    char tmp[32];
    bsi_sink_put(o, tmp, bsi_format_double(x, tmp));
}

static void emit_patch(const bs_patch *p, size_t first, bsi_sink *o)
{
    for (size_t i = 0; i < p->nctrl; i++) {
        bsi_sink_str(o, "v");
        for (size_t c = 0; c < 3; c++) {
            bsi_sink_str(o, " ");
            put_double(o, p->ctrl[3 * i + c]);
        }
        if (p->rational) {
            bsi_sink_str(o, " ");
            put_double(o, p->weights[i]);
        }
        bsi_sink_str(o, "\n");
    }
    bsi_sink_str(o, p->rational ? "cstype rat bezier\ndeg " : "cstype bezier\ndeg ");
    bsi_sink_uint(o, p->deg_u);
    bsi_sink_str(o, " ");
    bsi_sink_uint(o, p->deg_v);
    bsi_sink_str(o, "\nsurf 0 1 0 1");
    /* OBJ lists the net with u varying fastest; the library packs it with v fastest. */
    size_t k = 0;
    for (size_t j = 0; j <= p->deg_v; j++)
        for (size_t i = 0; i <= p->deg_u; i++, k++) {
            bsi_sink_str(o, k > 0 && k % REFS_PER_LINE == 0 ? " \\\n " : " ");
            bsi_sink_uint(o, first + i * (p->deg_v + 1) + j + 1);
        }
    bsi_sink_str(o, "\nparm u 0 1\nparm v 0 1\nend\n");
}

/* The text without a final NUL; o->len is its length even when it does not fit. */
static void emit(const bs_surface *s, bsi_sink *o)
{
    size_t count = bs_surface_count(s), first = 0;
    bsi_sink_str(o, "# libbezsurf: ");
    bsi_sink_uint(o, count);
    bsi_sink_str(o, count == 1 ? " Bezier patch\n" : " Bezier patches\n");
    for (size_t k = 0; k < count; k++) {
        const bs_patch *p = bs_surface_get(s, k);
        emit_patch(p, first, o);
        first += p->nctrl;
    }
}

bs_status bs_surface_write_obj(const bs_surface *s, char *buf, size_t cap, size_t *size)
{
    if (size == NULL)
        return BS_ERR_INVALID_ARG;
    bs_status st = bsi_check_surface3(s);
    if (st != BS_OK)
        return st;
    bsi_sink measure = {NULL, NULL, 0, 0, 0};
    emit(s, &measure);
    size_t need = measure.len + 1;
    if (buf != NULL) {
        if (cap < need)
            return BS_ERR_SIZE;
        bsi_sink o = {NULL, (unsigned char *)buf, cap, 0, 0};
        emit(s, &o);
        buf[o.len] = '\0';
    }
    *size = need;
    return BS_OK;
}

bs_status bs_surface_write_obj_file(const bs_surface *s, const char *path)
{
    return bsi_write_surface_file(s, path, bs_surface_write_obj);
}
