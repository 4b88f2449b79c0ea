/* relcol/relcol.h — the whole public API of librelcol in one include. */
#ifndef RELCOL_RELCOL_H
#define RELCOL_RELCOL_H

#include "relcol/version.h"
#include "relcol/status.h"
#include "relcol/vec.h"
#include "relcol/kinematics.h"
#include "relcol/law.h"
#include "relcol/contacts.h"
#include "relcol/toi.h"
#include "relcol/sim.h"
#include "relcol/perball.h"
#include "relcol/validity.h"
#include "relcol/moments.h"
#include "relcol/soft.h"
#include "relcol/gas1d.h"
#include "relcol/gravity.h"
#include "relcol/rng.h"
#include "relcol/wall.h"
#include "relcol/wall_thermal.h"

#endif
