/*
 * mesa_eval — evaluates GLSL ES 3.00 expressions with a real implementation: Mesa's llvmpipe,
 * through a surfaceless EGL context, as a vertex shader whose outputs are captured by
 * transform feedback (no window, no display server). The reference of tests/e2e/test_mesa.sh.
 *
 * Input (a file, or standard input): one case per line, `TYPE<TAB>EXPR`, where TYPE is the
 * GLSL type of EXPR (float, vec2..4, int, ivec2..4, uint, uvec2..4, bool, bvec2..4,
 * matCxR). A line starting with `@` is code placed before main() (functions, constants) for
 * every case after it. Blank lines and lines starting with `#` are skipped.
 *
 * Output: one line per case — its components in order (matrices column by column), floats
 * with 9 significant digits (enough to round-trip a binary32), ints and uints in decimal,
 * bools as true/false — or `error` when Mesa rejects the shader.
 *
 * Exit status: 0 when every case ran or was rejected, 1 when the GL could not be set up (no
 * EGL, no surfaceless platform, no OpenGL ES 3 context), 2 on bad input.
 */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_LINE = 8192, MAX_PRELUDE = 1 << 16, MAX_COMPONENTS = 16 };

typedef enum { COMP_FLOAT, COMP_INT, COMP_UINT, COMP_BOOL } comp_kind;

/* A GLSL type as captured: `columns` outputs of `rows` components each. */
typedef struct {
    comp_kind kind;
    int columns, rows;
} capture_type;

static int parse_vector(const char *t, const char *prefix, int *rows)
{
    size_t n = strlen(prefix);
    if (strncmp(t, prefix, n) != 0 || t[n] < '2' || t[n] > '4' || t[n + 1] != '\0')
        return 0;
    *rows = t[n] - '0';
    return 1;
}

/* mat2..mat4 and matCxR (C columns of R rows). */
static int parse_matrix(const char *t, capture_type *out)
{
    if (strncmp(t, "mat", 3) != 0 || t[3] < '2' || t[3] > '4')
        return 0;
    out->kind = COMP_FLOAT;
    out->columns = t[3] - '0';
    if (t[4] == '\0') {
        out->rows = out->columns;
        return 1;
    }
    if (t[4] != 'x' || t[5] < '2' || t[5] > '4' || t[6] != '\0')
        return 0;
    out->rows = t[5] - '0';
    return 1;
}

static int parse_type(const char *t, capture_type *out)
{
    static const struct {
        const char *scalar, *vector;
        comp_kind kind;
    } kinds[] = {{"float", "vec", COMP_FLOAT},
                 {"int", "ivec", COMP_INT},
                 {"uint", "uvec", COMP_UINT},
                 {"bool", "bvec", COMP_BOOL}};
    out->columns = 1;
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++) {
        out->kind = kinds[i].kind;
        out->rows = 1;
        if (strcmp(t, kinds[i].scalar) == 0 || parse_vector(t, kinds[i].vector, &out->rows))
            return 1;
    }
    return parse_matrix(t, out);
}

/* The GLSL type of one captured output: a column of a matrix, or the value itself with bools
 * carried as ints (a bool cannot be a shader output). */
static void output_type(const capture_type *c, char *buf, size_t size)
{
    static const char *scalar[] = {"float", "int", "uint", "int"};
    static const char *vector[] = {"vec", "ivec", "uvec", "ivec"};
    if (c->rows == 1)
        snprintf(buf, size, "%s", scalar[c->kind]);
    else
        snprintf(buf, size, "%s%d", vector[c->kind], c->rows);
}

static int build_source(char *src, size_t size, const char *prelude, const capture_type *c,
                        const char *type, const char *expr)
{
    char out_type[16];
    output_type(c, out_type, sizeof out_type);
    const char *flat = c->kind == COMP_FLOAT ? "" : "flat ";
    int n = snprintf(src, size,
                     "#version 300 es\nprecision highp float;\nprecision highp int;\n%s\n"
                     "%sout highp %s r0;\n%sout highp %s r1;\n%sout highp %s r2;\n"
                     "%sout highp %s r3;\n"
                     "void main() {\n  %s v = %s;\n",
                     prelude, flat, out_type, flat, out_type, flat, out_type, flat, out_type, type,
                     expr);
    for (int col = 0; col < 4 && n > 0 && (size_t)n < size; col++) {
        const char *conv = c->kind == COMP_BOOL ? out_type : "";
        if (col >= c->columns)
            n += snprintf(src + n, size - (size_t)n, "  r%d = %s(0);\n", col, out_type);
        else if (c->columns > 1)
            n += snprintf(src + n, size - (size_t)n, "  r%d = v[%d];\n", col, col);
        else
            n += snprintf(src + n, size - (size_t)n, "  r%d = %s(v);\n", col, conv);
    }
    if (n > 0 && (size_t)n < size)
        n += snprintf(src + n, size - (size_t)n, "  gl_Position = vec4(0.0);\n}\n");
    return n > 0 && (size_t)n < size ? 0 : -1;
}

static int verbose; /* -v: the compiler's log of each rejected case on stderr */

static void report_log(GLuint object, void (*get_log)(GLuint, GLsizei, GLsizei *, GLchar *))
{
    char log[2048];
    if (!verbose)
        return;
    get_log(object, sizeof log, NULL, log);
    fprintf(stderr, "mesa_eval: %s", log);
}

static GLuint compile(GLenum kind, const char *src)
{
    GLuint s = glCreateShader(kind);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        report_log(s, glGetShaderInfoLog);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

static const char fragment_source[] = "#version 300 es\nprecision highp float;\n"
                                      "out vec4 c;\nvoid main() { c = vec4(0.0); }\n";

/* Compiles and links the program capturing r0..r3 interleaved; 0 when Mesa rejects it. */
static GLuint link_program(const char *vertex_source)
{
    GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
    if (!vs)
        return 0;
    GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source);
    GLuint prog = glCreateProgram();
    glAttachShader(prog, vs);
    glAttachShader(prog, fs);
    static const char *const varyings[] = {"r0", "r1", "r2", "r3"};
    glTransformFeedbackVaryings(prog, 4, varyings, GL_INTERLEAVED_ATTRIBS);
    glLinkProgram(prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        report_log(prog, glGetProgramInfoLog);
        glDeleteProgram(prog);
        return 0;
    }
    return prog;
}

/* Runs one vertex through prog and reads the 4 × rows captured words into words. */
static int run_program(GLuint prog, int rows, unsigned int *words)
{
    GLuint buf;
    size_t bytes = (size_t)(4 * rows) * sizeof(unsigned int);
    glGenBuffers(1, &buf);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buf);
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, (GLsizeiptr)bytes, NULL, GL_STATIC_READ);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buf);
    glUseProgram(prog);
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, 1);
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    const void *p = glMapBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, (GLsizeiptr)bytes,
                                     GL_MAP_READ_BIT);
    int rc = p ? 0 : -1;
    if (p) {
        memcpy(words, p, bytes);
        glUnmapBuffer(GL_TRANSFORM_FEEDBACK_BUFFER);
    }
    glDeleteBuffers(1, &buf);
    return rc == 0 && glGetError() == GL_NO_ERROR ? 0 : -1;
}

static void print_component(comp_kind kind, unsigned int word)
{
    float f;
    switch (kind) {
    case COMP_FLOAT:
        memcpy(&f, &word, sizeof f);
        printf("%.9g", (double)f);
        break;
    case COMP_INT: printf("%d", (int)word); break;
    case COMP_UINT: printf("%u", word); break;
    case COMP_BOOL: printf("%s", word ? "true" : "false"); break;
    }
}

static void print_result(const capture_type *c, const unsigned int *words)
{
    for (int col = 0; col < c->columns; col++)
        for (int row = 0; row < c->rows; row++) {
            if (col || row)
                putchar(' ');
            print_component(c->kind, words[col * c->rows + row]);
        }
    putchar('\n');
}

static void run_case(const char *prelude, const char *type, const char *expr)
{
    static char src[MAX_PRELUDE + 2 * MAX_LINE];
    capture_type c;
    unsigned int words[MAX_COMPONENTS];
    GLuint prog = 0;
    if (parse_type(type, &c) && build_source(src, sizeof src, prelude, &c, type, expr) == 0)
        prog = link_program(src);
    if (prog && run_program(prog, c.rows, words) == 0)
        print_result(&c, words);
    else
        puts("error");
    if (prog)
        glDeleteProgram(prog);
}

/* Without a surface there is no default framebuffer, and a draw call, even with the
 * rasterizer discarded, needs a complete one: a 1×1 colour renderbuffer. */
static int bind_framebuffer(void)
{
    GLuint fbo, rb;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE ? 0 : -1;
}

static int setup_context(void)
{
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!get_display)
        return -1;
    EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL) || !eglBindAPI(EGL_OPENGL_ES_API))
        return -1;
    static const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
                                            EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    EGLConfig config;
    EGLint count = 0;
    if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count < 1)
        return -1;
    static const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, context_attribs);
    if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
        return -1;
    return bind_framebuffer();
}

/* Appends an `@` line to the prelude; -1 when it is full. */
static int add_prelude(char *prelude, size_t *used, const char *code)
{
    size_t n = strlen(code);
    if (*used + n + 2 > MAX_PRELUDE)
        return -1;
    memcpy(prelude + *used, code, n);
    *used += n;
    prelude[(*used)++] = '\n';
    prelude[*used] = '\0';
    return 0;
}

static int run_cases(FILE *in, const char *name)
{
    static char prelude[MAX_PRELUDE];
    char line[MAX_LINE];
    size_t used = 0;
    prelude[0] = '\0';
    for (int lineno = 1; fgets(line, sizeof line, in); lineno++) {
        line[strcspn(line, "\n")] = '\0';
        char *tab = strchr(line, '\t');
        if (line[0] == '\0' || line[0] == '#')
            continue;
        if (line[0] == '@' ? add_prelude(prelude, &used, line + 1) != 0 : !tab) {
            fprintf(stderr, "mesa_eval: %s:%d: expected TYPE<TAB>EXPR or @CODE\n", name, lineno);
            return 2;
        }
        if (line[0] == '@')
            continue;
        *tab = '\0';
        run_case(prelude, line, tab + 1);
    }
    return ferror(in) ? 2 : 0;
}

int main(int argc, char **argv)
{
    int first = 1;
    if (argc > 1 && strcmp(argv[1], "-v") == 0) {
        verbose = 1;
        first = 2;
    }
    if (argc > first + 1 || (argc == first + 1 && strcmp(argv[first], "--help") == 0)) {
        fprintf(stderr, "usage: mesa_eval [-v] [FILE]   (cases TYPE<TAB>EXPR; see the source)\n");
        return 2;
    }
    const char *name = argc == first + 1 ? argv[first] : "-";
    FILE *in = strcmp(name, "-") == 0 ? stdin : fopen(name, "r");
    if (!in) {
        perror(name);
        return 2;
    }
    if (setup_context() != 0) {
        fprintf(stderr, "mesa_eval: no OpenGL ES 3 context (surfaceless EGL, Mesa)\n");
        return 1;
    }
    int rc = run_cases(in, name);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        perror("mesa_eval: standard output");
        return 1;
    }
    return rc;
}
