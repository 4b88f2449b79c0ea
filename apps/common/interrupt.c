/* interrupt.c — Ctrl-C and SIGTERM for the apps that stop at once (all but relcol-sim,
 * which installs its own handler to write a restart state): the temporary files of the
 * atomic writers still open are removed, then the signal is raised again with its default
 * action, so the shell sees a death by SIGINT. The handler is installed even when the
 * signal was ignored: a script's `cmd &` starts cmd with SIGINT ignored, and kill -INT
 * must still stop it. */
#include <signal.h>
#include <string.h>
#include <unistd.h>

#include "app.h"

enum { SLOTS = 16, PATH_MAX_LEN = 4096 };
static char doomed[SLOTS][PATH_MAX_LEN];
static volatile sig_atomic_t in_use[SLOTS];

static void on_signal(int sig)
{
    for (int i = 0; i < SLOTS; i++)
        if (in_use[i])
            unlink(doomed[i]); /* (async-signal-safe) */
    signal(sig, SIG_DFL);
    raise(sig);
}

void app_interrupt_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGINT);
    sigaddset(&sa.sa_mask, SIGTERM);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

void app_interrupt_guard(const char *tmp)
{
    if (!tmp || strlen(tmp) >= PATH_MAX_LEN)
        return;
    for (int i = 0; i < SLOTS; i++)
        if (!in_use[i]) {
            strcpy(doomed[i], tmp);
            in_use[i] = 1; /* (set after the name is whole: the handler reads it then) */
            return;
        }
}

void app_interrupt_forget(const char *tmp)
{
    for (int i = 0; tmp && i < SLOTS; i++)
        if (in_use[i] && strcmp(doomed[i], tmp) == 0)
            in_use[i] = 0;
}
