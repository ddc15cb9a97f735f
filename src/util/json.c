/* The strict JSON reader of util/json.h: recursive descent over the grammar of RFC 8259 §2-§7,
 * depth bounded by SC_JSON_MAX_DEPTH so that hostile nesting cannot exhaust the stack. */
#include "util/json.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *s;
    size_t len, pos;
    char *err;
    size_t errsize;
    int failed;
} parser;

static void fail(parser *p, const char *fmt, ...)
{
    if (p->failed)
        return;
    p->failed = 1;
    size_t line = 1, column = 1;
    for (size_t i = 0; i < p->pos && i < p->len; i++, column++)
        if (p->s[i] == '\n') {
            line++;
            column = 0;
        }
    int n = snprintf(p->err, p->errsize, "line %zu, column %zu: ", line, column);
    if (n < 0 || (size_t)n >= p->errsize)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(p->err + n, p->errsize - (size_t)n, fmt, ap);
    va_end(ap);
}

static int peek(const parser *p) { return p->pos < p->len ? (unsigned char)p->s[p->pos] : -1; }

static void skip_space(parser *p)
{
    while (p->pos < p->len && strchr(" \t\r\n", p->s[p->pos]) && p->s[p->pos])
        p->pos++;
}

static sc_json *node(parser *p, sc_json_type type)
{
    sc_json *v = calloc(1, sizeof *v);
    if (!v)
        fail(p, "out of memory");
    else
        v->type = type;
    return v;
}

static int literal(parser *p, const char *word)
{
    size_t n = strlen(word);
    if (p->len - p->pos < n || memcmp(p->s + p->pos, word, n) != 0) {
        fail(p, "expected %s", word);
        return 0;
    }
    p->pos += n;
    return 1;
}

static size_t digits(parser *p)
{
    size_t n = 0;
    while (peek(p) >= '0' && peek(p) <= '9') {
        p->pos++;
        n++;
    }
    return n;
}

/* number = [ "-" ] int [ frac ] [ exp ]; int = "0" / digit1-9 *digit */
static sc_json *number(parser *p)
{
    size_t start = p->pos;
    if (peek(p) == '-')
        p->pos++;
    if (peek(p) == '0')
        p->pos++;
    else if (digits(p) == 0)
        return fail(p, "expected a digit"), NULL;
    if (peek(p) == '.') {
        p->pos++;
        if (digits(p) == 0)
            return fail(p, "expected a digit after '.'"), NULL;
    }
    if (peek(p) == 'e' || peek(p) == 'E') {
        p->pos++;
        if (peek(p) == '+' || peek(p) == '-')
            p->pos++;
        if (digits(p) == 0)
            return fail(p, "expected a digit in the exponent"), NULL;
    }
    char buf[SC_JSON_MAX_NUMBER + 1];
    size_t n = p->pos - start;
    if (n > SC_JSON_MAX_NUMBER) {
        p->pos = start;
        return fail(p, "number longer than %d characters", SC_JSON_MAX_NUMBER), NULL;
    }
    memcpy(buf, p->s + start, n);
    buf[n] = '\0';
    sc_json *v = node(p, SC_JSON_NUMBER);
    if (v)
        v->number = strtod(buf, NULL); /* overflow gives ±HUGE_VAL: the caller checks ranges */
    return v;
}

static int hex4(parser *p, unsigned *out)
{
    *out = 0;
    for (int i = 0; i < 4; i++) {
        int c = peek(p);
        int d = c >= '0' && c <= '9'   ? c - '0'
                : c >= 'a' && c <= 'f' ? c - 'a' + 10
                : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                       : -1;
        if (d < 0)
            return fail(p, "expected four hex digits after \\u"), 0;
        *out = *out * 16 + (unsigned)d;
        p->pos++;
    }
    return 1;
}

static size_t put_utf8(char *out, unsigned c)
{
    if (c < 0x80)
        return out[0] = (char)c, 1;
    if (c < 0x800)
        return out[0] = (char)(0xC0 | c >> 6), out[1] = (char)(0x80 | (c & 0x3F)), 2;
    if (c < 0x10000)
        return out[0] = (char)(0xE0 | c >> 12), out[1] = (char)(0x80 | (c >> 6 & 0x3F)),
               out[2] = (char)(0x80 | (c & 0x3F)), 3;
    return out[0] = (char)(0xF0 | c >> 18), out[1] = (char)(0x80 | (c >> 12 & 0x3F)),
           out[2] = (char)(0x80 | (c >> 6 & 0x3F)), out[3] = (char)(0x80 | (c & 0x3F)), 4;
}

/* The code point of a \u escape (p after "\u"), a surrogate pair joined; 0 on error. */
static unsigned unicode_escape(parser *p)
{
    unsigned c, low;
    if (!hex4(p, &c))
        return 0;
    if (c >= 0xDC00 && c <= 0xDFFF)
        return fail(p, "lone low surrogate"), 0;
    if (c >= 0xD800 && c <= 0xDBFF) {
        int pair = p->len - p->pos >= 2 && memcmp(p->s + p->pos, "\\u", 2) == 0;
        p->pos += pair ? 2 : 0;
        if (!pair || !hex4(p, &low) || low < 0xDC00 || low > 0xDFFF)
            return fail(p, "high surrogate without its low half"), 0;
        c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
    }
    if (c == 0)
        fail(p, "\\u0000 is not accepted");
    return c;
}

/* One character of a string body into out (at most 4 bytes); the bytes written, 0 on error. */
static size_t string_char(parser *p, char *out)
{
    int c = peek(p);
    if (c < 0)
        return fail(p, "unterminated string"), 0;
    if (c < 0x20)
        return fail(p, "control character in a string"), 0;
    p->pos++;
    if (c != '\\')
        return out[0] = (char)c, 1;
    static const char from[] = "\"\\/bfnrt", to[] = "\"\\/\b\f\n\r\t";
    int e = peek(p);
    const char *k = e > 0 ? strchr(from, e) : NULL;
    if (k) {
        p->pos++;
        return out[0] = to[k - from], 1;
    }
    if (e != 'u')
        return fail(p, "unknown escape"), 0;
    p->pos++;
    unsigned cp = unicode_escape(p);
    return cp ? put_utf8(out, cp) : 0;
}

/* A string (p at the opening quote), decoded into a malloc'ed buffer; NULL on error. The
 * decoded text is never longer than the source (an escape shrinks or keeps its length). */
static char *string_text(parser *p)
{
    size_t start = ++p->pos, end = start;
    while (end < p->len && p->s[end] != '"')
        end += p->s[end] == '\\' ? 2 : 1;
    char *buf = malloc((end < p->len ? end : p->len) - start + 5);
    if (!buf)
        return fail(p, "out of memory"), NULL;
    size_t n = 0;
    while (peek(p) != '"') {
        size_t k = string_char(p, buf + n);
        if (k == 0)
            return free(buf), NULL;
        n += k;
    }
    p->pos++;
    buf[n] = '\0';
    return buf;
}

static sc_json *value(parser *p, int depth);

/* The elements of an array or the members of an object (p after the opening bracket). */
static sc_json *container(parser *p, sc_json_type type, int depth)
{
    sc_json *v = node(p, type), **tail = v ? &v->child : NULL;
    int close = type == SC_JSON_ARRAY ? ']' : '}';
    skip_space(p);
    if (v && peek(p) == close) {
        p->pos++;
        return v;
    }
    while (v && !p->failed) {
        char *key = NULL;
        if (type == SC_JSON_OBJECT) {
            skip_space(p);
            if (peek(p) != '"') {
                fail(p, "expected a member name in quotes");
                break;
            }
            if (!(key = string_text(p)))
                break;
            skip_space(p);
            if (peek(p) != ':') {
                free(key);
                fail(p, "expected ':'");
                break;
            }
            p->pos++;
        }
        sc_json *item = value(p, depth + 1);
        if (!item) {
            free(key);
            break;
        }
        item->key = key;
        *tail = item;
        tail = &item->next;
        skip_space(p);
        int c = peek(p);
        p->pos += c == ',' || c == close;
        if (c == close)
            return v;
        if (c != ',')
            fail(p, c < 0 ? "unexpected end of input" : "expected ',' or '%c'", close);
    }
    sc_json_free(v);
    return NULL;
}

static sc_json *value(parser *p, int depth)
{
    if (depth > SC_JSON_MAX_DEPTH)
        return fail(p, "nested deeper than %d", SC_JSON_MAX_DEPTH), NULL;
    skip_space(p);
    int c = peek(p);
    if (c == '{' || c == '[') {
        p->pos++;
        return container(p, c == '{' ? SC_JSON_OBJECT : SC_JSON_ARRAY, depth);
    }
    if (c == '"') {
        char *s = string_text(p);
        sc_json *v = s ? node(p, SC_JSON_STRING) : NULL;
        if (v)
            v->string = s;
        else
            free(s);
        return v;
    }
    if (c == '-' || (c >= '0' && c <= '9'))
        return number(p);
    if (c == 't' || c == 'f') {
        sc_json *v = literal(p, c == 't' ? "true" : "false") ? node(p, SC_JSON_BOOL) : NULL;
        if (v)
            v->number = c == 't';
        return v;
    }
    if (c == 'n')
        return literal(p, "null") ? node(p, SC_JSON_NULL) : NULL;
    fail(p, c < 0 ? "unexpected end of input" : "unexpected character");
    return NULL;
}

sc_json *sc_json_parse(const char *text, size_t len, char *err, size_t errsize)
{
    parser p = {text, len, 0, err, errsize, 0};
    sc_json *v = value(&p, 0);
    skip_space(&p);
    if (v && p.pos < p.len) {
        fail(&p, "text after the value");
        sc_json_free(v);
        v = NULL;
    }
    return v;
}

void sc_json_free(sc_json *v)
{
    while (v) { /* along the list iteratively; into children at most SC_JSON_MAX_DEPTH deep */
        sc_json *next = v->next;
        sc_json_free(v->child);
        free(v->string);
        free(v->key);
        free(v);
        v = next;
    }
}

const sc_json *sc_json_member(const sc_json *v, const char *key)
{
    if (!v || v->type != SC_JSON_OBJECT)
        return NULL;
    for (const sc_json *m = v->child; m; m = m->next)
        if (strcmp(m->key, key) == 0)
            return m;
    return NULL;
}
