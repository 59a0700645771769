/* Surfaces: an ordered, growable array of owned patches. */
#include "surface/internal.h"

#include <stdlib.h>

struct bs_surface {
    size_t dim;        /* 0 until the first patch */
    size_t count, cap;
    bs_patch **patches;
};

bs_status bs_surface_create(bs_surface **out)
{
    if (out == NULL)
        return BS_ERR_INVALID_ARG;
    *out = calloc(1, sizeof(bs_surface));
    return *out ? BS_OK : BS_ERR_NO_MEMORY;
}

void bs_surface_destroy(bs_surface *s)
{
    if (s == NULL)
        return;
    for (size_t k = 0; k < s->count; k++)
        bs_patch_destroy(s->patches[k]);
    free(s->patches);
    free(s);
}

bs_status bs_surface_add(bs_surface *s, const bs_patch *p, size_t *index)
{
    if (s == NULL || p == NULL)
        return BS_ERR_INVALID_ARG;
    if (s->count > 0 && p->dim != s->dim)
        return BS_ERR_INCOMPATIBLE;
    if (s->count >= UINT32_MAX)
        return BS_ERR_SIZE;
    if (s->count == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 8;
        bs_patch **grown = realloc(s->patches, cap * sizeof(*grown)); // NOLINT(bugprone-sizeof-expression): an array of pointers
        if (grown == NULL)
            return BS_ERR_NO_MEMORY;
        s->patches = grown;
        s->cap = cap;
    }
    bs_patch *copy;
    bs_status st = bs_patch_clone(p, &copy);
    if (st != BS_OK)
        return st;
    s->patches[s->count] = copy;
    s->dim = p->dim;
    if (index != NULL)
        *index = s->count;
    s->count++;
    return BS_OK;
}

bs_status bsi_surface_adopt(bs_surface *s, bs_patch **patches, size_t n)
{
    if (n == 0)
        return BS_OK;
    size_t dim = s->count > 0 ? s->dim : patches[0]->dim;
    for (size_t k = 0; k < n; k++)
        if (patches[k]->dim != dim)
            return BS_ERR_INCOMPATIBLE;
    if (n > UINT32_MAX || s->count > UINT32_MAX - n)
        return BS_ERR_SIZE;
    if (s->count + n > s->cap) {
        size_t cap = s->cap ? s->cap : 8;
        while (cap < s->count + n)
            cap *= 2;
        bs_patch **grown = realloc(s->patches, cap * sizeof(*grown)); // NOLINT(bugprone-sizeof-expression): an array of pointers
        if (grown == NULL)
            return BS_ERR_NO_MEMORY;
        s->patches = grown;
        s->cap = cap;
    }
    for (size_t k = 0; k < n; k++)
        s->patches[s->count + k] = patches[k];
    s->count += n;
    s->dim = dim;
    return BS_OK;
}

bs_status bs_surface_clone(const bs_surface *s, bs_surface **out)
{
    if (out != NULL)
        *out = NULL;
    if (s == NULL || out == NULL)
        return BS_ERR_INVALID_ARG;
    bs_surface *copy;
    bs_status st = bs_surface_create(&copy);
    for (size_t k = 0; st == BS_OK && k < s->count; k++)
        st = bs_surface_add(copy, s->patches[k], NULL);
    if (st != BS_OK) {
        bs_surface_destroy(copy);
        return st;
    }
    *out = copy;
    return BS_OK;
}

size_t bs_surface_count(const bs_surface *s) { return s ? s->count : 0; }

size_t bs_surface_dim(const bs_surface *s) { return s ? s->dim : 0; }

const bs_patch *bs_surface_get(const bs_surface *s, size_t i)
{
    return (s != NULL && i < s->count) ? s->patches[i] : NULL;
}
