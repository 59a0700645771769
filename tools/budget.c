/* The meshes of tessellate and render: counted first and refused over the triangle budget, so that
 * a small file or a fine tolerance cannot make the tool take gigabytes and minutes. */
#include "cmds.h"

int cli_parse_budget(const char *cmd, const char *val, size_t *budget)
{
    return cli_parse_size(val, budget) ? CLI_OK : cli_usage_error(cmd, "bad triangle count", val);
}

int cli_tessellate(const char *cmd, const bs_surface *s, const bs_tess_options *o, size_t budget, bs_mesh **out)
{
    size_t nt = 0;
    bs_status st = bs_surface_tessellate_count(s, o, NULL, &nt);
    if (st == BS_OK && budget != 0 && nt > budget)
        return cli_fail(cmd, CLI_INPUT,
                        "the mesh would have %zu triangles, more than the budget of %zu (--max-triangles N "
                        "raises it, 0 removes it)",
                        nt, budget);
    if (st == BS_OK) {
        bs_tess_options b = *o;
        b.max_triangles = budget;
        st = bs_surface_tessellate(s, &b, out);
    }
    if (st == BS_OK)
        return CLI_OK;
    /* A surface that is not 3-D, a rate out of range or a mesh past 32-bit indices is the input's;
     * the rest is the library's. */
    int input = st == BS_ERR_DIMENSION || st == BS_ERR_DOMAIN || st == BS_ERR_SIZE;
    return cli_fail(cmd, input ? CLI_INPUT : CLI_INTERNAL, "%s", bs_status_string(st));
}
