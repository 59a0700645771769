/* ISO 10303-21 text -> instances: the HEADER section is checked and dropped, each DATA instance
 * `#N = NAME(...);` or `#N = ( A(...) B(...) );` becomes one record and its parameters nodes in one
 * flat array. Nested lists are read with an explicit stack of at most STP_NEST_MAX levels. */
#include "io/step.h"

#include <string.h>

typedef struct lexer {
    stp *s;
    size_t pos, line, col;
} lexer;

static bs_status fail_here(const lexer *L, const char *what)
{
    if (L->pos >= L->s->len)
        return bsi_fail(L->s->err, L->line, L->col, "unexpected end of file: expected %s", what);
    return bsi_fail(L->s->err, L->line, L->col, "expected %s", what);
}

static void advance(lexer *L, size_t n)
{
    for (size_t k = 0; k < n && L->pos < L->s->len; k++) {
        if (L->s->text[L->pos++] == '\n') {
            L->line++;
            L->col = 1;
        } else {
            L->col++;
        }
    }
}

/* Skip white space and comments; BS_ERR_PARSE for an unterminated comment. */
static bs_status skip(lexer *L)
{
    const char *t = L->s->text;
    while (L->pos < L->s->len) {
        char c = t[L->pos];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            advance(L, 1);
        } else if (c == '/' && L->pos + 1 < L->s->len && t[L->pos + 1] == '*') {
            size_t line = L->line, col = L->col;
            advance(L, 2);
            while (L->pos + 1 < L->s->len && !(t[L->pos] == '*' && t[L->pos + 1] == '/'))
                advance(L, 1);
            if (L->pos + 1 >= L->s->len)
                return bsi_fail(L->s->err, line, col, "comment not closed");
            advance(L, 2);
        } else {
            break;
        }
    }
    return BS_OK;
}

static int peek(const lexer *L) { return L->pos < L->s->len ? (unsigned char)L->s->text[L->pos] : -1; }

static int is_alpha(int c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
static int is_digit(int c) { return c >= '0' && c <= '9'; }

/* A keyword at the cursor (optionally starting with '!'): its length, 0 if none. */
static size_t keyword_len(const lexer *L)
{
    size_t k = L->pos;
    const char *t = L->s->text;
    if (k < L->s->len && t[k] == '!')
        k++;
    if (k >= L->s->len || !is_alpha((unsigned char)t[k]))
        return 0;
    while (k < L->s->len && (is_alpha((unsigned char)t[k]) || is_digit((unsigned char)t[k]) || t[k] == '-'))
        k++;
    return k - L->pos;
}

/* The keyword at the cursor equals word (then consumed). */
static int accept_word(lexer *L, const char *word)
{
    size_t n = keyword_len(L), w = strlen(word);
    if (n != w || memcmp(L->s->text + L->pos, word, w) != 0)
        return 0;
    advance(L, n);
    return 1;
}

static bs_status expect(lexer *L, int c, const char *what)
{
    bs_status st = skip(L);
    if (st != BS_OK)
        return st;
    if (peek(L) != c)
        return fail_here(L, what);
    advance(L, 1);
    return BS_OK;
}

static bs_status push(lexer *L, unsigned char kind, size_t *at)
{
    stp *s = L->s;
    bs_status st = bsi_grow(&s->nodes, sizeof(stp_node), 1);
    if (st != BS_OK)
        return st;
    stp_node *n = (stp_node *)s->nodes.data + s->nodes.n;
    memset(n, 0, sizeof *n);
    n->kind = kind;
    n->span = 1;
    *at = s->nodes.n++;
    return BS_OK;
}

static stp_node *node(lexer *L, size_t k) { return (stp_node *)L->s->nodes.data + k; }

/* A number token: INT or REAL node. */
static bs_status number(lexer *L)
{
    const char *t = L->s->text;
    size_t k = L->pos, real = 0;
    if (t[k] == '+' || t[k] == '-')
        k++;
    while (k < L->s->len && (is_digit((unsigned char)t[k]) || t[k] == '.' || t[k] == 'E' || t[k] == 'e' ||
                             ((t[k] == '+' || t[k] == '-') && (t[k - 1] == 'E' || t[k - 1] == 'e')))) {
        real |= t[k] == '.' || t[k] == 'E' || t[k] == 'e';
        k++;
    }
    double x;
    if (bsi_parse_double(t + L->pos, k - L->pos, &x) != 1)
        return bsi_fail(L->s->err, L->line, L->col, "bad number '%.*s'", (int)(k - L->pos > 40 ? 40 : k - L->pos),
                        t + L->pos);
    size_t at;
    bs_status st = push(L, real ? STP_REAL : STP_INT, &at);
    if (st != BS_OK)
        return st;
    node(L, at)->v.num = x;
    advance(L, k - L->pos);
    return BS_OK;
}

/* A string '...' ('' inside), or a binary "...": kept raw. */
static bs_status string(lexer *L)
{
    const char *t = L->s->text;
    char q = t[L->pos];
    size_t line = L->line, col = L->col, k = L->pos + 1;
    for (;;) {
        if (k >= L->s->len)
            return bsi_fail(L->s->err, line, col, "string not closed");
        if (t[k] == q) {
            if (q == '\'' && k + 1 < L->s->len && t[k + 1] == '\'') {
                k += 2;
                continue;
            }
            break;
        }
        k++;
    }
    size_t at;
    bs_status st = push(L, STP_STR, &at);
    if (st != BS_OK)
        return st;
    node(L, at)->v.off = L->pos + 1;
    node(L, at)->len = (uint32_t)(k - L->pos - 1);
    advance(L, k + 1 - L->pos);
    return BS_OK;
}

/* The list at the cursor ('(' ... ')'), keywords in it typed values KEYWORD(...). */
static bs_status list(lexer *L)
{
    size_t stack[2 * STP_NEST_MAX + 2], depth = 0, at;
    bs_status st = expect(L, '(', "'('");
    if (st != BS_OK || (st = push(L, STP_LIST, &at)) != BS_OK)
        return st;
    stack[depth++] = at;
    int need_sep = 0;
    while (depth > 0) {
        if ((st = skip(L)) != BS_OK)
            return st;
        int c = peek(L);
        stp_node *top = node(L, stack[depth - 1]);
        if (c == ')') {
            advance(L, 1);
            top->span = (uint32_t)(L->s->nodes.n - stack[depth - 1]);
            depth--;
            if (depth > 0 && node(L, stack[depth - 1])->kind == STP_TYPED) {
                node(L, stack[depth - 1])->span = (uint32_t)(L->s->nodes.n - stack[depth - 1]);
                depth--;
            }
            need_sep = 1;
            continue;
        }
        if (need_sep) {
            if (c != ',')
                return fail_here(L, "',' or ')'");
            advance(L, 1);
            if ((st = skip(L)) != BS_OK)
                return st;
            c = peek(L);
        }
        need_sep = 1;
        top->count++;
        size_t kw = 0;
        if (c == '(' || (kw = keyword_len(L)) > 0) {
            if (depth >= STP_NEST_MAX)
                return bsi_fail(L->s->err, L->line, L->col, "lists nested deeper than %d", STP_NEST_MAX);
            if (c != '(') {
                if ((st = push(L, STP_TYPED, &at)) != BS_OK)
                    return st;
                node(L, at)->v.off = L->pos;
                node(L, at)->len = (uint32_t)kw;
                stack[depth++] = at;
                advance(L, kw);
                if ((st = expect(L, '(', "'(' after a keyword")) != BS_OK)
                    return st;
            } else {
                advance(L, 1);
            }
            if ((st = push(L, STP_LIST, &at)) != BS_OK)
                return st;
            stack[depth++] = at;
            need_sep = 0;
        } else if (c == '#') {
            advance(L, 1);
            size_t k = L->pos, id;
            while (k < L->s->len && is_digit((unsigned char)L->s->text[k]))
                k++;
            if (bsi_parse_size(L->s->text + L->pos, k - L->pos, SIZE_MAX / 2, &id) != 1)
                return fail_here(L, "an entity number after '#'");
            if ((st = push(L, STP_REF, &at)) != BS_OK)
                return st;
            node(L, at)->v.ref = id;
            advance(L, k - L->pos);
        } else if (c == '\'' || c == '"') {
            if ((st = string(L)) != BS_OK)
                return st;
        } else if (c == '.') {
            size_t k = L->pos + 1;
            while (k < L->s->len && (is_alpha((unsigned char)L->s->text[k]) || is_digit((unsigned char)L->s->text[k])))
                k++;
            if (k >= L->s->len || L->s->text[k] != '.' || k == L->pos + 1)
                return fail_here(L, "an enumeration .NAME.");
            if ((st = push(L, STP_ENUM, &at)) != BS_OK)
                return st;
            node(L, at)->v.off = L->pos + 1;
            node(L, at)->len = (uint32_t)(k - L->pos - 1);
            advance(L, k + 1 - L->pos);
        } else if (c == '$' || c == '*') {
            if ((st = push(L, c == '$' ? STP_UNSET : STP_DERIVED, &at)) != BS_OK)
                return st;
            advance(L, 1);
        } else if (c == '+' || c == '-' || is_digit(c)) {
            if ((st = number(L)) != BS_OK)
                return st;
        } else {
            return fail_here(L, "a parameter");
        }
    }
    return BS_OK;
}

/* NAME(...) as a TYPED node followed by its list. */
static bs_status typed(lexer *L, size_t *at)
{
    bs_status st = skip(L);
    size_t kw = keyword_len(L);
    if (st != BS_OK)
        return st;
    if (kw == 0)
        return fail_here(L, "an entity name");
    if ((st = push(L, STP_TYPED, at)) != BS_OK)
        return st;
    node(L, *at)->v.off = L->pos;
    node(L, *at)->len = (uint32_t)kw;
    advance(L, kw);
    if ((st = list(L)) != BS_OK)
        return st;
    node(L, *at)->span = (uint32_t)(L->s->nodes.n - *at);
    return BS_OK;
}

/* One instance after its '#'. */
static bs_status instance(lexer *L)
{
    stp_inst in;
    in.line = (uint32_t)L->line;
    in.col = (uint32_t)L->col;
    advance(L, 1);
    size_t k = L->pos;
    while (k < L->s->len && is_digit((unsigned char)L->s->text[k]))
        k++;
    if (bsi_parse_size(L->s->text + L->pos, k - L->pos, SIZE_MAX / 2, &in.id) != 1)
        return fail_here(L, "an entity number after '#'");
    advance(L, k - L->pos);
    bs_status st = expect(L, '=', "'='");
    if (st != BS_OK || (st = skip(L)) != BS_OK)
        return st;
    if (peek(L) == '(') {
        size_t part;
        advance(L, 1);
        if ((st = push(L, STP_LIST, &in.root)) != BS_OK)
            return st;
        for (;;) {
            if ((st = skip(L)) != BS_OK)
                return st;
            if (peek(L) == ')')
                break;
            if ((st = typed(L, &part)) != BS_OK)
                return st;
            node(L, in.root)->count++;
        }
        advance(L, 1);
        node(L, in.root)->span = (uint32_t)(L->s->nodes.n - in.root);
    } else if ((st = typed(L, &in.root)) != BS_OK) {
        return st;
    }
    if ((st = expect(L, ';', "';' after an instance")) != BS_OK || (st = bsi_grow(&L->s->inst, sizeof in, 1)) != BS_OK)
        return st;
    ((stp_inst *)L->s->inst.data)[L->s->inst.n++] = in;
    return BS_OK;
}

/* The HEADER section's entries: parsed, then dropped. */
static bs_status header(lexer *L)
{
    bs_status st;
    for (;;) {
        if ((st = skip(L)) != BS_OK)
            return st;
        if (accept_word(L, "ENDSEC"))
            return expect(L, ';', "';' after ENDSEC");
        size_t mark = L->s->nodes.n, at;
        if ((st = typed(L, &at)) != BS_OK || (st = expect(L, ';', "';' after a header entry")) != BS_OK)
            return st;
        L->s->nodes.n = mark;
    }
}

bs_status bsi_stp_lex(stp *s)
{
    lexer L = {s, 0, 1, 1};
    bs_status st = skip(&L);
    if (st != BS_OK)
        return st;
    if (!accept_word(&L, "ISO-10303-21"))
        return fail_here(&L, "ISO-10303-21; (not a STEP file)");
    if ((st = expect(&L, ';', "';'")) != BS_OK || (st = skip(&L)) != BS_OK)
        return st;
    if (!accept_word(&L, "HEADER"))
        return fail_here(&L, "HEADER;");
    if ((st = expect(&L, ';', "';'")) != BS_OK || (st = header(&L)) != BS_OK)
        return st;
    int data = 0;
    for (;;) {
        if ((st = skip(&L)) != BS_OK)
            return st;
        if (accept_word(&L, "END-ISO-10303-21"))
            break;
        if (!accept_word(&L, "DATA"))
            return fail_here(&L, data ? "DATA or END-ISO-10303-21;" : "DATA;");
        data = 1;
        if ((st = skip(&L)) != BS_OK)
            return st;
        if (peek(&L) == '(') { /* DATA('name', (schema)) of several sections */
            size_t mark = s->nodes.n;
            if ((st = list(&L)) != BS_OK)
                return st;
            s->nodes.n = mark;
        }
        if ((st = expect(&L, ';', "';' after DATA")) != BS_OK)
            return st;
        for (;;) {
            if ((st = skip(&L)) != BS_OK)
                return st;
            if (accept_word(&L, "ENDSEC"))
                break;
            if (peek(&L) != '#')
                return fail_here(&L, "an instance #N = ... or ENDSEC;");
            if ((st = instance(&L)) != BS_OK)
                return st;
        }
        if ((st = expect(&L, ';', "';' after ENDSEC")) != BS_OK)
            return st;
    }
    if (!data)
        return fail_here(&L, "a DATA section");
    return expect(&L, ';', "';' after END-ISO-10303-21");
}
