/* cli_load: a scenario loaded for a command, with a line on stderr for every
 * setting the file gave that an engine's check replaced. */
#include <stdio.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"

int dv_cli_load_scenario(const char *command, const char *path, const dv_cli_list *sets,
                         dv_scenario *sc, dv_error *err) {
  const int status = dv_engine_load_scenario(path, sets->items, sets->n, sc, err);
  for (size_t i = 0; !status && i < sc->nsections; i++)
    if (sc->replaced[i][0])
      fprintf(stderr, "diskval %s: %s: engines.%s: given %s, replaced (%s)\n", command, path,
              sc->sections[i]->name, sc->replaced[i], sc->derived[i]);
  return status;
}
