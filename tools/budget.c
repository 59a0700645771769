/* The meshes of tessellate and render: counted first and refused over the triangle budget, so that
 * a small file or a fine tolerance cannot make the tool take gigabytes and minutes; likewise the
 * closest points of render --closest, estimated from the patches' degrees. */
#include "cmds.h"

#include <string.h>

int cli_parse_budget(const char *cmd, const char *val, size_t *budget)
{
    return cli_parse_size(val, budget) ? CLI_OK : cli_usage_error(cmd, "bad triangle count", val);
}

int cli_parse_query_budget(const char *cmd, const char *val, size_t *budget)
{
    return cli_parse_size(val, budget) ? CLI_OK : cli_usage_error(cmd, "bad query work", val);
}

int cli_parse_method(const char *cmd, const char *val, int *method)
{
    if (strcmp(val, "per-patch") == 0)
        *method = BS_TESS_PER_PATCH;
    else if (strcmp(val, "subdivide") == 0)
        *method = BS_TESS_SUBDIVIDE;
    else
        return cli_usage_error(cmd, "unknown method", val);
    return CLI_OK;
}

int cli_tessellate(const char *cmd, const bs_surface *s, const bs_tess_options *o, size_t budget, bs_mesh **out)
{
    size_t nt = 0;
    bs_tess_options b = *o;
    b.max_triangles = budget;
    bs_status st = BS_OK;
    if (o->method == BS_TESS_SUBDIVIDE) {
        /* counting builds the trees: the tessellator refuses while they are still small instead */
        st = bs_surface_tessellate(s, &b, out);
        if (st == BS_ERR_SIZE && budget != 0)
            return cli_fail(cmd, CLI_INPUT,
                            "the mesh would have more triangles than the budget of %zu (--max-triangles N "
                            "raises it, 0 removes it)",
                            budget);
    } else {
        st = bs_surface_tessellate_count(s, o, NULL, &nt);
        if (st == BS_OK && budget != 0 && nt > budget)
            return cli_fail(cmd, CLI_INPUT,
                            "the mesh would have %zu triangles, more than the budget of %zu (--max-triangles N "
                            "raises it, 0 removes it)",
                            nt, budget);
        if (st == BS_OK)
            st = bs_surface_tessellate(s, &b, out);
    }
    if (st == BS_OK)
        return CLI_OK;
    /* A surface that is not 3-D, a rate out of range or a mesh past 32-bit indices is the input's;
     * the rest is the library's. */
    int input = st == BS_ERR_DIMENSION || st == BS_ERR_DOMAIN || st == BS_ERR_SIZE;
    return cli_fail(cmd, input ? CLI_INPUT : CLI_INTERNAL, "%s", bs_status_string(st));
}

/* One closest point on a patch of degrees (m, n) repeats subdivisions of its net, each about its
 * (m + 1)(n + 1) control points times m + n + 2 operations: that product is the step the budget
 * counts. Measured, a step costs 0.1 to 0.5 microseconds from degree 3 to degree 64 (docs/cli.md). */
static unsigned long long closest_steps(const bs_patch *p)
{
    unsigned long long m = bs_patch_degree_u(p), n = bs_patch_degree_v(p);
    return (m + 1) * (n + 1) * (m + n + 2);
}

int cli_query_budget(const char *cmd, const bs_surface *s, size_t n, size_t budget)
{
    /* the locator searches the few patches near each point: the costliest one prices a point */
    unsigned long long worst = 0;
    size_t worst_at = 0;
    for (size_t k = 0; k < bs_surface_count(s); k++) {
        unsigned long long w = closest_steps(bs_surface_get(s, k));
        if (w > worst)
            worst = w, worst_at = k;
    }
    unsigned long long work = worst * (unsigned long long)n; /* n <= 100000: no overflow */
    if (budget == 0 || work <= budget)
        return CLI_OK;
    const bs_patch *p = bs_surface_get(s, worst_at);
    return cli_fail(cmd, CLI_INPUT,
                    "--closest %zu would take about %llu steps of work (%llu a point on patches of degree %zux%zu), "
                    "more than the budget of %zu (--max-query-work N raises it, 0 removes it)",
                    n, work, worst, bs_patch_degree_u(p), bs_patch_degree_v(p), budget);
}
