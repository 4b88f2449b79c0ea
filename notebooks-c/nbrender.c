/* nbrender.c — renders a literate C notebook to Markdown: its Markdown cells (block
 * comments opening with "md"), its code cells (fenced C), and its captured output placed
 * where a Markdown cell says "@output NAME", with "@@figure F.png" lines as images.
 * Usage: nbrender NOTEBOOK.c OUTPUT.txt PAGE.md   (PAGE.md written atomically). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    char *name;
    char *text; /* captured lines, figures as "@@figure ..." kept for rendering */
    int used;
} section;

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n) {
        free(s);
        s = NULL;
    }
    if (s)
        s[n] = '\0';
    fclose(f);
    return s;
}

static int is_blank(const char *a, const char *b)
{
    for (; a < b; a++)
        if (*a != ' ' && *a != '\t' && *a != '\n' && *a != '\r')
            return 0;
    return 1;
}

static void emit_section(FILE *o, section *s)
{
    s->used = 1;
    const char *p = s->text;
    int in_fence = 0;
    while (*p) {
        const char *e = strchr(p, '\n');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len > 9 && strncmp(p, "@@figure ", 9) == 0) {
            if (in_fence) {
                fputs("```\n", o);
                in_fence = 0;
            }
            fprintf(o, "\n![%.*s](%.*s)\n\n", (int)(len - 9), p + 9, (int)(len - 9), p + 9);
        } else {
            if (!in_fence) {
                fputs("```text\n", o);
                in_fence = 1;
            }
            fprintf(o, "%.*s\n", (int)len, p);
        }
        p += len + (e ? 1 : 0);
    }
    if (in_fence)
        fputs("```\n", o);
}

static section *find(section *s, int n, const char *name, size_t len)
{
    for (int i = 0; i < n; i++)
        if (strlen(s[i].name) == len && strncmp(s[i].name, name, len) == 0)
            return &s[i];
    return NULL;
}

static void emit_markdown(FILE *o, const char *a, const char *b, section *secs, int nsec)
{
    /* one line at a time: strip a leading " * " comment decoration, expand @output */
    while (a < b) {
        const char *e = memchr(a, '\n', (size_t)(b - a));
        if (!e)
            e = b;
        const char *l = a;
        if (e - l >= 2 && l[0] == ' ' && l[1] == '*' && (e - l == 2 || l[2] == ' '))
            l += (e - l == 2) ? 2 : 3;
        if (e - l > 8 && strncmp(l, "@output ", 8) == 0) {
            const char *nm = l + 8;
            size_t nl = (size_t)(e - nm);
            while (nl && (nm[nl - 1] == ' ' || nm[nl - 1] == '\r'))
                nl--;
            section *s = find(secs, nsec, nm, nl);
            if (s)
                emit_section(o, s);
            else
                fprintf(o, "*(no output named %.*s)*\n", (int)nl, nm);
        } else {
            fprintf(o, "%.*s\n", (int)(e - l), l);
        }
        a = e + 1;
    }
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: nbrender NOTEBOOK.c OUTPUT.txt PAGE.md\n");
        return 2;
    }
    char *src = slurp(argv[1]), *out = slurp(argv[2]);
    if (!src || !out) {
        fprintf(stderr, "nbrender: cannot read %s\n", src ? argv[2] : argv[1]);
        return 2;
    }
    /* split the captured output into named sections */
    section secs[256];
    int nsec = 0;
    for (char *p = out; p && *p;) {
        char *e = strchr(p, '\n');
        if (e)
            *e = '\0';
        if (strncmp(p, "@@output ", 9) == 0 && nsec < 256) {
            secs[nsec].name = p + 9;
            secs[nsec].text = e ? e + 1 : p + strlen(p);
            secs[nsec].used = 0;
            if (nsec > 0) /* terminate the previous section's text */
                p[-1] = '\0';
            nsec++;
        }
        if (e)
            *e = '\n';
        p = e ? e + 1 : NULL;
    }
    for (int i = 0; i < nsec; i++) {
        char *nl = strchr(secs[i].name, '\n');
        if (nl)
            *nl = '\0';
    }

    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp", argv[3]);
    FILE *o = fopen(tmp, "w");
    if (!o) {
        fprintf(stderr, "nbrender: cannot write %s\n", tmp);
        return 2;
    }
    const char *p = src;
    for (;;) {
        const char *m = strstr(p, "/*md");
        const char *code_end = m ? m : p + strlen(p);
        if (!is_blank(p, code_end)) {
            while (*p == '\n')
                p++;
            const char *ce = code_end;
            while (ce > p && (ce[-1] == '\n' || ce[-1] == ' '))
                ce--;
            fprintf(o, "\n```c\n%.*s\n```\n\n", (int)(ce - p), p);
        }
        if (!m)
            break;
        const char *body = m + 4;
        while (*body && *body != '\n')
            body++;
        const char *end = strstr(body, "*/");
        if (!end)
            end = body + strlen(body);
        emit_markdown(o, body + (*body == '\n'), end, secs, nsec);
        p = *end ? end + 2 : end;
        while (*p == '\n')
            p++;
    }
    for (int i = 0; i < nsec; i++)
        if (!secs[i].used && strcmp(secs[i].name, "summary") != 0) {
            fprintf(o, "\n### Output: %s\n\n", secs[i].name);
            emit_section(o, &secs[i]);
        }
    section *sum = find(secs, nsec, "summary", 7);
    if (sum) {
        fputs("\n---\nNotebook checks:\n\n", o);
        emit_section(o, sum);
    }
    if (fclose(o) != 0 || rename(tmp, argv[3]) != 0) {
        fprintf(stderr, "nbrender: cannot write %s\n", argv[3]);
        remove(tmp);
        return 2;
    }
    free(src);
    free(out);
    return 0;
}
