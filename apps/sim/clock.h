/* clock.h — whether a run's clock can resolve its balls' motion (clock.c). */
#ifndef RELCOL_SIM_CLOCK_H
#define RELCOL_SIM_CLOCK_H

#include "scenario.h"

/* 0, or -1 with the reason in err (APP_ERR_LEN) when the doubles near the run's start or end
 * time are so far apart that the fastest a ball can go moves more than 1e-3 of the smallest
 * radius within one of their steps. */
int sim_check_clock(const scn_scenario *s, char *err);

#endif
