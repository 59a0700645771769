/* libFuzzer target for sequences of API calls. The input is decoded into a control net (any
 * degrees, dims, weights and values, valid or not) and then a list of operations with arbitrary
 * parameters and view sizes. Oracles besides "no crash, no leak, no out-of-bounds access":
 * - failed calls write nothing: every output buffer is filled with a canary bit pattern first
 *   and compared afterwards; new-handle outputs are set to NULL;
 * - successful calls write nothing outside the view elements (the gaps between strided elements
 *   and the slack beyond count keep their canaries);
 * - a tame patch (finite, moderate coordinates and weights) evaluated at finite parameters in
 *   [0,1] gives finite values;
 * - the halves of a split agree with the parent within a tolerance relative to the net's size. */
#include <bezsurf.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_PTS 24
#define MAX_STRIDE 3

typedef struct reader {
    const uint8_t *p;
    size_t n;
} reader;

static unsigned rd_byte(reader *r)
{
    if (r->n == 0)
        return 0;
    r->n--;
    return *r->p++;
}

/* A double: usually a small dyadic value in [-8,8], sometimes raw bits (NaN, Inf, huge). */
static double rd_value(reader *r)
{
    unsigned tag = rd_byte(r);
    if (tag < 224)
        return ((double)rd_byte(r) - 128.0) / 16.0 + (double)(tag % 8) / 256.0;
    uint64_t bits = 0;
    for (int k = 0; k < 8; k++)
        bits = bits << 8 | rd_byte(r);
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

/* A parameter: usually in [0,1] (k/255), sometimes slightly outside, sometimes raw bits. */
/* A derivative order: mostly small; the top bytes reach past BS_MAX_DEGREE (high orders of
 * rational patches cost O(k^4) per point, which would slow the fuzzer down). */
static unsigned rd_order(reader *r)
{
    unsigned b = rd_byte(r);
    return b < 240 ? b % 6 : b - 190;
}

static double rd_param(reader *r)
{
    unsigned tag = rd_byte(r);
    if (tag < 200)
        return (double)rd_byte(r) / 255.0;
    if (tag < 240)
        return ((double)rd_byte(r) - 64.0) / 64.0;
    return rd_value(r);
}

static const uint64_t CANARY_BITS = 0x7ff4dead5eedbeefull;

static void canary_fill(double *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        memcpy(&x[k], &CANARY_BITS, sizeof CANARY_BITS);
}

static int is_canary(const double *x)
{
    uint64_t b;
    memcpy(&b, x, sizeof b);
    return b == CANARY_BITS;
}

/* One output view over a canary-filled buffer: one guard element at each end, elements every
 * `step` doubles (negative strides run backwards from the high end). */
typedef struct oview {
    double buf[2 + MAX_PTS * MAX_STRIDE];
    size_t len;
    size_t step;
    int negative;
} oview;

static void oview_make(oview *o, bs_view *v, size_t count, size_t step, int negative, int misalign)
{
    o->step = step;
    o->negative = negative;
    o->len = 2 + (count ? count * step : 0);
    canary_fill(o->buf, sizeof o->buf / sizeof o->buf[0]);
    v->count = count;
    v->stride = step == 1 && !negative ? 0 : (ptrdiff_t)(step * sizeof(double)) * (negative ? -1 : 1);
    v->data = negative && count ? o->buf + 1 + (count - 1) * step : o->buf + 1;
    if (misalign)
        v->data = (double *)(void *)((char *)v->data + 4);
}

/* Index in buf of element k. */
static size_t oview_index(const oview *o, size_t count, size_t k)
{
    return o->negative ? 1 + (count - 1 - k) * o->step : 1 + k * o->step;
}

/* 1 if every double is a canary except elements 0..written-1 of the view. */
static int oview_clean(const oview *o, size_t count, size_t written)
{
    for (size_t i = 0; i < sizeof o->buf / sizeof o->buf[0]; i++) {
        int element = 0;
        if (i >= 1 && written > 0) {
            size_t off = i - 1;
            if (off % o->step == 0) {
                size_t k = off / o->step;
                element = o->negative ? (k < count && count - 1 - k < written) : k < written;
            }
        }
        if (!element && !is_canary(&o->buf[i]))
            return 0;
    }
    return 1;
}

typedef struct oset {
    oview o[BS_MAX_DIM];
    bs_view v[BS_MAX_DIM];
    size_t count;
} oset;

static void oset_make(oset *s, reader *r, size_t n)
{
    unsigned shape = rd_byte(r);
    size_t count = n;
    if (shape % 7 == 1 && count > 0)
        count--; /* one too short */
    else if (shape % 7 == 2 && count < MAX_PTS)
        count++; /* room to spare */
    size_t step = 1 + (shape >> 3) % MAX_STRIDE;
    int negative = (shape >> 5) & 1;
    int misalign = shape == 255;
    s->count = count;
    for (size_t c = 0; c < BS_MAX_DIM; c++)
        oview_make(&s->o[c], &s->v[c], count, step, negative, misalign && c == 0);
}

static int oset_clean(const oset *s, size_t dim, size_t written)
{
    for (size_t c = 0; c < BS_MAX_DIM; c++)
        if (!oview_clean(&s->o[c], s->count, c < dim ? written : 0))
            return 0;
    return 1;
}

static double oset_get(const oset *s, size_t c, size_t k) { return s->o[c].buf[oview_index(&s->o[c], s->count, k)]; }

/* The state of one run. */
typedef struct state {
    bs_patch *p;
    int tame;     /* finite coordinates below 1e6, weights in [1/64, 64]: no overflow possible */
    double scale; /* 1 + largest absolute coordinate (tame patches) */
} state;

#define REQUIRE(c) \
    do {           \
        if (!(c))  \
            abort(); \
    } while (0)

static void measure(state *st)
{
    size_t dim = bs_patch_dim(st->p), np = (bs_patch_degree_u(st->p) + 1) * (bs_patch_degree_v(st->p) + 1);
    double *c = malloc(np * dim * sizeof(double)), *w = malloc(np * sizeof(double));
    st->tame = 0;
    st->scale = 1.0;
    if (c != NULL && w != NULL && bs_patch_get_ctrl(st->p, c, np * dim, w, np) == BS_OK) {
        st->tame = 1;
        for (size_t k = 0; k < np * dim; k++) {
            if (!(fabs(c[k]) < 1e6))
                st->tame = 0;
            else if (fabs(c[k]) + 1.0 > st->scale)
                st->scale = fabs(c[k]) + 1.0;
        }
        for (size_t k = 0; k < np; k++)
            if (!(w[k] >= 1.0 / 64 && w[k] <= 64))
                st->tame = 0;
    }
    free(c);
    free(w);
}

/* n parameters into a canary-guarded input view (or a NULL view now and then). */
typedef struct iview {
    double buf[MAX_PTS * MAX_STRIDE + 1];
    bs_cview v;
    int unit; /* every parameter finite and in [0,1] */
} iview;

static void iview_make(iview *iv, reader *r, size_t n)
{
    unsigned shape = rd_byte(r);
    size_t step = 1 + shape % MAX_STRIDE;
    canary_fill(iv->buf, sizeof iv->buf / sizeof iv->buf[0]);
    iv->unit = 1;
    for (size_t k = 0; k < n; k++) {
        double t = rd_param(r);
        iv->unit &= t >= 0.0 && t <= 1.0;
        iv->buf[k * step] = t;
    }
    iv->v.data = shape == 255 ? NULL : iv->buf;
    iv->v.count = shape % 11 == 3 && n > 0 ? n - 1 : n;
    iv->v.stride = (ptrdiff_t)(step * sizeof(double));
}

static int finite_all(const oset *s, size_t dim, size_t n)
{
    for (size_t c = 0; c < dim; c++)
        for (size_t k = 0; k < n; k++)
            if (!isfinite(oset_get(s, c, k)))
                return 0;
    return 1;
}

static void op_eval(state *st, reader *r)
{
    size_t n = rd_byte(r) % (MAX_PTS + 1), dim = bs_patch_dim(st->p);
    unsigned which = rd_byte(r);
    iview u, v;
    iview_make(&u, r, n);
    iview_make(&v, r, n);
    static oset out[5]; /* pos, du, dv (or deriv), nrm, spare */
    unsigned char kind[MAX_PTS + 2];
    for (int k = 0; k < 4; k++)
        oset_make(&out[k], r, n);
    memset(kind, 0xA5, sizeof kind);
    const bs_view *pv = which & 1 ? out[0].v : NULL, *dv1 = which & 2 ? out[1].v : NULL,
                  *dv2 = which & 4 ? out[2].v : NULL;
    size_t written = 0, wdim = dim;
    int want[4] = {pv != NULL, dv1 != NULL, dv2 != NULL, 0};
    bs_status s;
    switch ((which >> 3) % 4) {
    case 0:
        s = bs_patch_eval(st->p, n, &u.v, &v.v, pv, dv1, dv2);
        break;
    case 1: {
        unsigned ku = rd_order(r), kv = rd_order(r);
        s = bs_patch_eval_deriv(st->p, ku, kv, n, &u.v, &v.v, out[1].v);
        want[0] = want[2] = 0;
        want[1] = 1;
        break;
    }
    case 2:
        s = bs_patch_eval_normal(st->p, n, &u.v, &v.v, pv, which & 64 ? out[3].v : NULL, which & 128 ? kind + 1 : NULL);
        want[1] = want[2] = 0;
        want[3] = (which & 64) != 0;
        if (s == BS_OK)
            REQUIRE(dim == 3);
        break;
    default: {
        /* grid: nu x nv = n points at most */
        size_t nu = n ? 1 + rd_byte(r) % n : 0, nv = nu ? n / nu : 0;
        int nrm = dim == 3 ? (which & 64) != 0 : (which & 64) && (which & 128);
        s = bs_patch_eval_grid(st->p, nu, &u.v, nv, &v.v, pv, dv1, dv2, nrm ? out[3].v : NULL,
                               nrm && (which & 32) ? kind + 1 : NULL);
        want[3] = nrm;
        n = nu * nv;
        break;
    }
    }
    if (s == BS_OK)
        written = n;
    for (int k = 0; k < 4; k++) {
        size_t d = k == 3 ? 3 : wdim;
        REQUIRE(oset_clean(&out[k], d, want[k] ? written : 0));
    }
    REQUIRE(kind[0] == 0xA5 && kind[MAX_PTS + 1] == 0xA5);
    if (s != BS_OK)
        for (size_t k = 1; k <= MAX_PTS; k++)
            REQUIRE(kind[k] == 0xA5);
    if (s == BS_OK && st->tame && u.unit && v.unit)
        for (int k = 0; k < 4; k++)
            if (want[k])
                REQUIRE(finite_all(&out[k], k == 3 ? 3 : wdim, n));
}

/* The patch q agrees with p after the map (s,r) -> (a + s*(b-a), c + r*(d-c)) at a few points. */
static void agree(const bs_patch *p, const bs_patch *q, double a, double b, double c, double d, double scale)
{
    size_t dim = bs_patch_dim(p);
    double us[9], vs[9], qu[9], qv[9], pp[BS_MAX_DIM][9], qp[BS_MAX_DIM][9];
    bs_view pvw[BS_MAX_DIM], qvw[BS_MAX_DIM];
    for (int k = 0; k < 9; k++) {
        qu[k] = (k % 3) / 2.0;
        qv[k] = (k / 3) / 2.0;
        us[k] = a + qu[k] * (b - a);
        vs[k] = c + qv[k] * (d - c);
    }
    for (size_t i = 0; i < dim; i++) {
        pvw[i] = (bs_view){pp[i], 9, 0};
        qvw[i] = (bs_view){qp[i], 9, 0};
    }
    bs_cview cu = {us, 9, 0}, cv = {vs, 9, 0}, cqu = {qu, 9, 0}, cqv = {qv, 9, 0};
    REQUIRE(bs_patch_eval(p, 9, &cu, &cv, pvw, NULL, NULL) == BS_OK);
    REQUIRE(bs_patch_eval(q, 9, &cqu, &cqv, qvw, NULL, NULL) == BS_OK);
    double tol = 1e-7 * scale;
    for (size_t i = 0; i < dim; i++)
        for (int k = 0; k < 9; k++)
            REQUIRE(fabs(pp[i][k] - qp[i][k]) <= tol);
}

static bs_patch *const NOT_SET = (bs_patch *)(uintptr_t)0x10;

/* Replace the current patch by q (or keep it) as the input chooses. */
static void adopt(state *st, bs_patch *q, int take)
{
    if (take) {
        bs_patch_destroy(st->p);
        st->p = q;
        measure(st);
    } else {
        bs_patch_destroy(q);
    }
}

static void op_split(state *st, reader *r)
{
    int dir = (int)(rd_byte(r) % 3);
    double t = rd_param(r);
    bs_patch *lo = NOT_SET, *hi = NOT_SET;
    bs_status s = bs_patch_split(st->p, dir, t, &lo, &hi);
    if (s != BS_OK) {
        REQUIRE(lo == NULL && hi == NULL);
        REQUIRE(dir == 2 || !(t > 0.0 && t < 1.0) || s == BS_ERR_NONFINITE || s == BS_ERR_NO_MEMORY);
        return;
    }
    REQUIRE(dir != 2 && t > 0.0 && t < 1.0 && lo != NULL && hi != NULL && lo != hi);
    if (st->tame) {
        double ua = dir == BS_DIR_U ? t : 0.0, va = dir == BS_DIR_V ? t : 0.0;
        agree(st->p, lo, 0.0, dir == BS_DIR_U ? t : 1.0, 0.0, dir == BS_DIR_V ? t : 1.0, st->scale);
        agree(st->p, hi, ua, 1.0, va, 1.0, st->scale);
    }
    unsigned keep = rd_byte(r) % 3;
    adopt(st, lo, keep == 1);
    adopt(st, hi, keep == 2);
}

static void op_subpatch(state *st, reader *r)
{
    double a = rd_param(r), b = rd_param(r), c = rd_param(r), d = rd_param(r);
    bs_patch *q = NOT_SET;
    bs_status s = bs_patch_subpatch(st->p, a, b, c, d, &q);
    if (s != BS_OK) {
        REQUIRE(q == NULL);
        return;
    }
    REQUIRE(q != NULL && isfinite(a) && isfinite(b) && isfinite(c) && isfinite(d) && a != b && c != d);
    if (st->tame && a >= 0 && a <= 1 && b >= 0 && b <= 1 && c >= 0 && c <= 1 && d >= 0 && d <= 1 &&
        fabs(b - a) > 1e-3 && fabs(d - c) > 1e-3)
        agree(st->p, q, a, b, c, d, st->scale * 1e3);
    adopt(st, q, rd_byte(r) % 4 == 0);
}

static void op_elevate(state *st, reader *r)
{
    /* mostly small raises (high degrees make every later call slow); the top bytes reach past the limit */
    size_t ru = rd_byte(r), rv = rd_byte(r);
    ru = ru < 240 ? ru % 4 : ru - 190;
    rv = rv < 240 ? rv % 4 : rv - 190;
    bs_patch *q = NOT_SET;
    bs_status s = bs_patch_elevate(st->p, ru, rv, &q);
    int fits = bs_patch_degree_u(st->p) + ru <= BS_MAX_DEGREE && bs_patch_degree_v(st->p) + rv <= BS_MAX_DEGREE;
    if (s != BS_OK) {
        REQUIRE(q == NULL && (s == BS_ERR_DEGREE) == !fits);
        return;
    }
    REQUIRE(fits && q != NULL && bs_patch_degree_u(q) == bs_patch_degree_u(st->p) + ru);
    if (st->tame)
        agree(st->p, q, 0.0, 1.0, 0.0, 1.0, st->scale);
    adopt(st, q, rd_byte(r) % 4 == 0);
}

static void op_misc(state *st, reader *r)
{
    size_t dim = bs_patch_dim(st->p);
    bs_patch *q = NOT_SET, *four[4] = {NOT_SET, NOT_SET, NOT_SET, NOT_SET};
    bs_status s;
    switch (rd_byte(r) % 6) {
    case 0:
        s = bs_patch_split4(st->p, rd_param(r), rd_param(r), four);
        for (int k = 0; k < 4; k++) {
            REQUIRE(s == BS_OK ? four[k] != NULL : four[k] == NULL);
            bs_patch_destroy(four[k]);
        }
        return;
    case 1: {
        unsigned ku = rd_order(r), kv = rd_order(r);
        s = bs_patch_derivative(st->p, ku, kv, &q);
        break;
    }
    case 2: {
        double buf[2 + (BS_MAX_DEGREE + 1) * BS_MAX_DIM], wb[2 + BS_MAX_DEGREE + 1];
        size_t cap = rd_byte(r) * 4u, wcap = rd_byte(r);
        if (cap > (BS_MAX_DEGREE + 1) * BS_MAX_DIM)
            cap = (BS_MAX_DEGREE + 1) * BS_MAX_DIM;
        if (wcap > BS_MAX_DEGREE + 1)
            wcap = BS_MAX_DEGREE + 1;
        canary_fill(buf, sizeof buf / sizeof buf[0]);
        canary_fill(wb, sizeof wb / sizeof wb[0]);
        int dir = (int)(rd_byte(r) % 3);
        s = bs_patch_isocurve(st->p, dir, rd_param(r), buf + 1, cap, wb + 1, wcap);
        size_t cnt = dir == BS_DIR_U ? bs_patch_degree_v(st->p) + 1 : bs_patch_degree_u(st->p) + 1;
        size_t wc = s == BS_OK ? cnt * dim : 0, ww = s == BS_OK ? cnt : 0;
        for (size_t k = 0; k < sizeof buf / sizeof buf[0]; k++)
            REQUIRE((k >= 1 && k <= wc) || is_canary(&buf[k]));
        for (size_t k = 0; k < sizeof wb / sizeof wb[0]; k++)
            REQUIRE((k >= 1 && k <= ww) || is_canary(&wb[k]));
        return;
    }
    case 3: {
        double aff[BS_MAX_DIM * (BS_MAX_DIM + 1)];
        for (size_t k = 0; k < dim * (dim + 1); k++)
            aff[k] = rd_value(r);
        s = bs_patch_transform(st->p, aff, &q);
        break;
    }
    case 4:
        s = rd_byte(r) & 1 ? bs_patch_swap_uv(st->p, &q) : bs_patch_reverse(st->p, (int)(rd_byte(r) % 3), &q);
        break;
    default: {
        double lo[BS_MAX_DIM + 1], hi[BS_MAX_DIM + 1];
        canary_fill(lo, BS_MAX_DIM + 1);
        canary_fill(hi, BS_MAX_DIM + 1);
        REQUIRE(bs_patch_bounds(st->p, lo, hi) == BS_OK);
        for (size_t c = 0; c <= BS_MAX_DIM; c++)
            REQUIRE(c < dim ? lo[c] <= hi[c] : is_canary(&lo[c]) && is_canary(&hi[c]));
        return;
    }
    }
    REQUIRE(s == BS_OK ? q != NULL : q == NULL);
    if (s == BS_OK)
        adopt(st, q, rd_byte(r) % 4 == 0);
}

static void op_surface(state *st, reader *r)
{
    bs_surface *sf = NULL;
    if (bs_surface_create(&sf) != BS_OK)
        return;
    size_t copies = 1 + rd_byte(r) % 3;
    for (size_t k = 0; k < copies; k++)
        REQUIRE(bs_surface_add(sf, st->p, NULL) == BS_OK);
    size_t n = rd_byte(r) % (MAX_PTS + 1);
    uint32_t ids[MAX_PTS];
    for (size_t k = 0; k < n; k++)
        ids[k] = rd_byte(r) % (copies + 1); /* id == copies is out of range */
    iview u, v;
    iview_make(&u, r, n);
    iview_make(&v, r, n);
    static oset pos;
    oset_make(&pos, r, n);
    bs_status s = bs_surface_eval(sf, n, ids, &u.v, &v.v, pos.v, NULL, NULL);
    REQUIRE(oset_clean(&pos, bs_patch_dim(st->p), s == BS_OK ? n : 0));
    if (bs_patch_dim(st->p) == 3) {
        /* tessellation: small rates (and 0, invalid), or an adaptive tolerance of any value */
        bs_mesh *mesh = (bs_mesh *)(void *)NOT_SET;
        unsigned how = rd_byte(r);
        size_t ru = rd_byte(r) % 9, rv = rd_byte(r) % 9;
        double tol = rd_value(r);
        int aflags = (int)(how >> 1) % 4;
        /* A valid tolerance becomes at least 5% of the net's diagonal: tiny tolerances are legal but
         * make 1024 x 1024 vertices per patch (BS_TESS_MAX_RATE), seconds per input under the fuzzer; so
         * are high degrees, whose second differences are large. */
        if (isfinite(tol) && tol > 0.0) {
            if (bs_patch_degree_u(st->p) > 3 || bs_patch_degree_v(st->p) > 3 || !st->tame)
                how |= 1; /* uniform rates only: adaptive ones reach the cap here */
            tol = 0.05 + fabs(tol);
            aflags |= BS_TESS_RELATIVE;
        }
        bs_status ts = how & 1 ? bs_surface_tessellate_uniform(sf, ru, rv, (int)(how >> 1) % 4, &mesh)
                               : bs_surface_tessellate_adaptive(sf, tol, aflags, &mesh);
        REQUIRE(ts == BS_OK ? mesh != NULL : mesh == NULL);
        if (ts == BS_OK && st->tame && bs_mesh_vertex_count(mesh) <= 4096) {
            static double xyz[3][4096];
            bs_view mv[3] = {{xyz[0], 4096, 0}, {xyz[1], 4096, 0}, {xyz[2], 4096, 0}};
            REQUIRE(bs_mesh_copy_positions(mesh, mv) == BS_OK);
            for (size_t k = 0; k < bs_mesh_vertex_count(mesh); k++)
                REQUIRE(isfinite(xyz[0][k]) && isfinite(xyz[1][k]) && isfinite(xyz[2][k]));
        }
        bs_mesh_destroy(ts == BS_OK ? mesh : NULL);
    }
    size_t need = 0;
    if (bs_patch_dim(st->p) == 3 && bs_surface_write_bpt(sf, NULL, 0, &need) == BS_OK) {
        char *text = malloc(need);
        bs_surface *back = NULL;
        REQUIRE(text != NULL && bs_surface_write_bpt(sf, text, need, &need) == BS_OK);
        REQUIRE(bs_surface_read_bpt(text, need - 1, NULL, &back) == BS_OK);
        REQUIRE(bs_surface_count(back) == copies);
        bs_surface_destroy(back);
        free(text);
    }
    bs_surface_destroy(sf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    reader r = {data, size};
    size_t m = rd_byte(&r), n = rd_byte(&r), dim = rd_byte(&r) % 11;
    /* Mostly small degrees; the top of the byte range reaches past BS_MAX_DEGREE. */
    m = m < 240 ? m % 8 : m - 190; /* 50..65 */
    n = n < 240 ? n % 8 : n - 190;
    unsigned rational = rd_byte(&r);
    int valid_shape = m <= BS_MAX_DEGREE && n <= BS_MAX_DEGREE && dim >= 1 && dim <= BS_MAX_DIM;
    size_t mm = m > BS_MAX_DEGREE ? BS_MAX_DEGREE : m, nn = n > BS_MAX_DEGREE ? BS_MAX_DEGREE : n;
    size_t np = (mm + 1) * (nn + 1), dd = dim > BS_MAX_DIM ? BS_MAX_DIM : dim;
    double *ctrl = malloc((np * dd + 1) * sizeof(double)), *w = malloc(np * sizeof(double));
    REQUIRE(ctrl != NULL && w != NULL);
    int finite = 1;
    for (size_t k = 0; k < np * dd; k++) {
        ctrl[k] = rd_value(&r);
        finite &= isfinite(ctrl[k]);
    }
    for (size_t k = 0; k < np; k++) {
        w[k] = rational & 2 ? rd_value(&r) : 0.5 + (double)(rd_byte(&r) % 8) / 4.0;
        finite &= isfinite(w[k]) && w[k] > 0;
    }
    state st = {NOT_SET, 0, 1.0};
    bs_status s = bs_patch_create(m, n, dim, ctrl, rational & 1 ? w : NULL, &st.p);
    free(ctrl);
    free(w);
    if (s != BS_OK) {
        REQUIRE(st.p == NULL);
        REQUIRE(!valid_shape || !finite || s == BS_ERR_NONFINITE);
        return 0;
    }
    REQUIRE(valid_shape && st.p != NULL);
    measure(&st);
    for (int step = 0; step < 8 && r.n > 0; step++) {
        switch (rd_byte(&r) % 6) {
        case 0:
        case 1:
            op_eval(&st, &r);
            break;
        case 2:
            op_split(&st, &r);
            break;
        case 3:
            op_subpatch(&st, &r);
            break;
        case 4:
            if (rd_byte(&r) & 1)
                op_elevate(&st, &r);
            else
                op_misc(&st, &r);
            break;
        default:
            op_surface(&st, &r);
            break;
        }
    }
    bs_patch_destroy(st.p);
    return 0;
}
