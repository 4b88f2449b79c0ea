/* progress.c — a progress bar that draws only on a terminal, so pipes, CI logs and the
 * tests' captured stderr stay clean. */
#include <unistd.h>

#include "app.h"

enum { BAR_WIDTH = 40 };

void app_progress_init(app_progress *p, const char *label, size_t total)
{
    p->label = label;
    p->total = total;
    p->tty = isatty(STDERR_FILENO);
    p->last_pct = -1;
}

void app_progress_update(app_progress *p, size_t done)
{
    if (!p->tty || p->total == 0)
        return;
    int pct = (int)(100.0 * (double)done / (double)p->total);
    if (pct == p->last_pct)
        return;
    p->last_pct = pct;
    int fill = pct * BAR_WIDTH / 100;
    fprintf(stderr, "\r%s [", p->label);
    for (int i = 0; i < BAR_WIDTH; i++)
        fputc(i < fill ? '#' : '.', stderr);
    fprintf(stderr, "] %3d%%", pct);
    fflush(stderr);
}

void app_progress_stop(app_progress *p)
{
    if (p->tty && p->total != 0 && p->last_pct >= 0)
        fputc('\n', stderr);
}

void app_progress_done(app_progress *p)
{
    if (!p->tty || p->total == 0)
        return;
    app_progress_update(p, p->total);
    fputc('\n', stderr);
}
