/* dv_league: the words of a cell's outcome. */
#include "league.h"

const char *dv_league_outcome_name(dv_league_outcome o) {
  static const char *const NAMES[] = {"reached", "not reached", "cannot model", "not run"};
  return o >= DV_LEAGUE_REACHED && o <= DV_LEAGUE_NOT_RUN ? NAMES[o] : "not run";
}
