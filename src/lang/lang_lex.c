/* The lexer of the language (GLSL ES 3.00 §3): comments, integer literals (decimal, octal,
 * hexadecimal, `u` suffix), float literals (`f` suffix), identifiers, operators; `#version`
 * and `#extension` lines are skipped, other preprocessor directives are an error. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "lang/lang_compiler.h"

void lex_init(lexer *lx, const char *src)
{
    lx->pos = src;
    lx->line = 1;
    lx->line_start = src;
}

static void newline(lexer *lx, const char *after)
{
    lx->line++;
    lx->line_start = after;
}

/* Skips a directive line if it is one we accept; 0, or -1 for another directive. */
static int skip_directive(lexer *lx)
{
    const char *p = lx->pos + 1;
    while (*p == ' ' || *p == '\t')
        p++;
    int known = strncmp(p, "version", 7) == 0 || strncmp(p, "extension", 9) == 0;
    if (!known)
        return -1;
    lx->pos += strcspn(lx->pos, "\n");
    return 0;
}

/* 1 if the current position starts a line (only blanks before it). */
static int at_line_start(const lexer *lx)
{
    for (const char *p = lx->line_start; p < lx->pos; p++)
        if (*p != ' ' && *p != '\t' && *p != '\r')
            return 0;
    return 1;
}

/* Skips blanks, comments and accepted directives; NULL, or a message for a bad one. */
static const char *skip_space(lexer *lx)
{
    for (;;) {
        char c = *lx->pos;
        if (c == '\n') {
            newline(lx, ++lx->pos);
        } else if (isspace((unsigned char)c)) {
            lx->pos++;
        } else if (c == '/' && lx->pos[1] == '/') {
            lx->pos += strcspn(lx->pos, "\n");
        } else if (c == '/' && lx->pos[1] == '*') {
            const char *p = lx->pos + 2;
            lexer start = *lx;
            for (; *p && !(p[0] == '*' && p[1] == '/'); p++)
                if (*p == '\n')
                    newline(lx, p + 1);
            if (!*p) { /* reported where it starts */
                *lx = start;
                return "unterminated comment";
            }
            lx->pos = p + 2;
        } else if (c == '#' && at_line_start(lx)) {
            if (skip_directive(lx) < 0)
                return "preprocessor directives are not supported (except #version, #extension)";
        } else {
            return NULL;
        }
    }
}

static int is_ident_char(int c) { return isalnum(c) || c == '_'; }

/* An integer literal: decimal, 0x hexadecimal or 0 octal, optional u/U. */
static void scan_integer(const char *s, ltoken *t)
{
    int base = 10;
    const char *p = s;
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))
        base = 16, p += 2;
    else if (p[0] == '0')
        base = 8;
    const char *digits = p;
    double value = 0.0;
    for (;; p++) {
        int d = isdigit((unsigned char)*p)    ? *p - '0'
                : isxdigit((unsigned char)*p) ? tolower((unsigned char)*p) - 'a' + 10
                                              : -1;
        if (d < 0 || d >= base)
            break;
        if (value <= 4294967295.0)
            value = value * base + d;
    }
    t->kind = T_INT;
    if (*p == 'u' || *p == 'U')
        p++, t->kind = T_UINT;
    t->num = value;
    if (base == 16 && p == digits)
        t->kind = T_BAD, t->msg = "hexadecimal literal without digits";
    else if (value > 4294967295.0)
        t->kind = T_BAD, t->msg = "integer literal does not fit in 32 bits";
    t->len = (int)(p - s);
}

/* A float literal if s starts one (digits with '.' or an exponent): its length, else 0. */
static int scan_float(const char *s)
{
    const char *p = s;
    int digits = 0, is_float = 0;
    while (isdigit((unsigned char)*p))
        p++, digits++;
    if (*p == '.') {
        is_float = 1;
        for (p++; isdigit((unsigned char)*p); p++)
            digits++;
    }
    if (!digits)
        return 0;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        q += *q == '+' || *q == '-';
        if (isdigit((unsigned char)*q)) {
            while (isdigit((unsigned char)*q))
                q++;
            p = q, is_float = 1;
        }
    }
    if (is_float && (*p == 'f' || *p == 'F'))
        p++;
    return is_float ? (int)(p - s) : 0;
}

static void scan_number(const char *s, ltoken *t)
{
    int flen = scan_float(s);
    if (flen) {
        sc_literal lit = sc_literal_read(s, NULL);
        t->kind = T_FLOAT;
        t->num = lit.value;
        t->tie = lit.tie;
        t->len = flen;
    } else {
        scan_integer(s, t);
    }
    if (t->kind != T_BAD && is_ident_char((unsigned char)s[t->len])) {
        t->kind = T_BAD;
        t->msg = "malformed number";
    }
    if (t->kind == T_BAD)
        while (is_ident_char((unsigned char)s[t->len]) || s[t->len] == '.')
            t->len++;
}

static const struct {
    const char *text;
    int code;
} multi[] = {
    {"<<=", P_SHL_ASSIGN}, {">>=", P_SHR_ASSIGN}, {"<<", P_SHL},        {">>", P_SHR},
    {"<=", P_LE},          {">=", P_GE},          {"==", P_EQ},         {"!=", P_NE},
    {"&&", P_AND},         {"||", P_OR},          {"^^", P_XOR},        {"++", P_INC},
    {"--", P_DEC},         {"+=", P_ADD_ASSIGN},  {"-=", P_SUB_ASSIGN}, {"*=", P_MUL_ASSIGN},
    {"/=", P_DIV_ASSIGN},  {"%=", P_MOD_ASSIGN},  {"&=", P_AND_ASSIGN}, {"|=", P_OR_ASSIGN},
    {"^=", P_XOR_ASSIGN},
};

static void scan_punct(const char *s, ltoken *t)
{
    for (size_t i = 0; i < sizeof multi / sizeof multi[0]; i++) {
        size_t n = strlen(multi[i].text);
        if (strncmp(s, multi[i].text, n) == 0) {
            t->kind = T_PUNCT;
            t->punct = multi[i].code;
            t->len = (int)n;
            return;
        }
    }
    t->len = 1;
    t->punct = (unsigned char)*s;
    t->kind = strchr("+-*/%<>=!~&|^?:;,.()[]{}", *s) ? T_PUNCT : T_BAD;
    t->msg = "unexpected character";
}

void lex_next(lexer *lx, ltoken *t)
{
    const char *bad = skip_space(lx);
    memset(t, 0, sizeof *t);
    t->start = lx->pos;
    t->line = lx->line;
    t->column = (int)(lx->pos - lx->line_start) + 1;
    unsigned char c = (unsigned char)*lx->pos;
    if (bad) {
        t->kind = T_BAD;
        t->msg = bad;
        t->len = 1;
    } else if (c == '\0') {
        t->kind = T_END;
    } else if (isdigit(c) || (c == '.' && isdigit((unsigned char)lx->pos[1]))) {
        scan_number(lx->pos, t);
    } else if (isalpha(c) || c == '_') {
        while (is_ident_char((unsigned char)lx->pos[t->len]))
            t->len++;
        t->kind = T_IDENT;
    } else {
        scan_punct(lx->pos, t);
    }
    lx->pos += t->len;
    if (bad) /* nothing follows a bad comment or directive */
        lx->pos += strlen(lx->pos);
}

void next(compiler *cs)
{
    if (cs->tok.start) /* none before the first token */
        cs->prev_end = cs->tok.start + cs->tok.len;
    lex_next(&cs->lx, &cs->tok);
}

ltoken peek(const compiler *cs)
{
    lexer copy = cs->lx;
    ltoken t;
    lex_next(&copy, &t);
    return t;
}

int is_punct(const compiler *cs, int p) { return cs->tok.kind == T_PUNCT && cs->tok.punct == p; }

int token_is_word(const ltoken *t, const char *word)
{
    return t->kind == T_IDENT && (int)strlen(word) == t->len &&
           strncmp(t->start, word, (size_t)t->len) == 0;
}

int is_word(const compiler *cs, const char *word) { return token_is_word(&cs->tok, word); }
