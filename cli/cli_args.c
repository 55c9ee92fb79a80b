/* cli_args: the option parser every command shares (cli_args.h). */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_args.h"

#define HELP_ID (-2)  /* getopt_long's val for --help */
#define SET_ID (-3)   /* and for --set */
#define QUIET_ID (-4) /* and for --quiet */

int dv_cli_list_push(dv_cli_list *list, const char *item) {
  if (list->n == list->cap) {
    const size_t cap = list->cap ? 2 * list->cap : 8;
    const char **items = realloc(list->items, cap * sizeof *items);
    if (!items) return -1;
    list->items = items, list->cap = cap;
  }
  list->items[list->n++] = item;
  return 0;
}

/* text as a finite number in [lo, hi], the whole text; whole: an integer */
static int parse_number(const char *text, double lo, double hi, int whole, double *v) {
  char *end;
  errno = 0;
  *v = strtod(text, &end);
  if (end == text || *end || errno == ERANGE || !isfinite(*v)) return -1;
  if (whole && *v != floor(*v)) return -1;
  return *v >= lo && *v <= hi ? 0 : -1;
}

/* store the value of option o given as text */
static int take(const dv_cli_command *cmd, const dv_cli_option *o, const char *text) {
  double v;
  switch (o->kind) {
    case DV_CLI_FLAG:
      *(int *)o->value = 1;
      return 0;
    case DV_CLI_TEXT:
      *(const char **)o->value = text;
      return 0;
    case DV_CLI_LIST:
      return dv_cli_list_push(o->value, text) ? dv_cli_usage_error(cmd->name, "out of memory") : 0;
    case DV_CLI_REAL:
    case DV_CLI_INT:
      if (parse_number(text, o->lo, o->hi, o->kind == DV_CLI_INT, &v))
        return dv_cli_usage_error(cmd->name, "--%s: '%s' is not a %s in [%g, %g]", o->name, text,
                                  o->kind == DV_CLI_INT ? "whole number" : "finite number", o->lo,
                                  o->hi);
      if (o->kind == DV_CLI_INT)
        *(int *)o->value = (int)v;
      else
        *(double *)o->value = v;
      return 0;
  }
  return -1;
}

int dv_cli_parse(const dv_cli_command *cmd, int argc, char **argv, dv_cli_args *out) {
  memset(out, 0, sizeof *out);
  struct option *longs = calloc(cmd->noptions + 4, sizeof *longs);
  unsigned char *given = calloc(cmd->noptions + 1, 1); /* a value already taken */
  if (!longs || !given)
    return free(longs), free(given), dv_cli_usage_error(cmd->name, "out of memory");
  for (size_t i = 0; i < cmd->noptions; i++)
    longs[i] = (struct option){
        cmd->options[i].name, cmd->options[i].kind == DV_CLI_FLAG ? no_argument : required_argument,
        NULL, (int)i};
  longs[cmd->noptions] = (struct option){"help", no_argument, NULL, HELP_ID};
  longs[cmd->noptions + 1] = (struct option){"set", required_argument, NULL, SET_ID};
  longs[cmd->noptions + 2] = (struct option){"quiet", no_argument, NULL, QUIET_ID};
  int status = DV_CLI_RUN;
  opterr = 0;
  optind = 0; /* glibc: start afresh, so a process may parse more than once */
  for (int c; status == DV_CLI_RUN && (c = getopt_long(argc, argv, ":h", longs, NULL)) != -1;) {
    if (c == 'h' || c == HELP_ID) {
      fputs(cmd->help, stdout);
      status = fflush(stdout) || ferror(stdout)
                   ? dv_cli_error(cmd->name, "cannot write the output: %s", strerror(errno))
                   : DV_EXIT_OK;
    } else if (c == SET_ID) {
      const char *eq = strchr(optarg, '='), *dot = strchr(optarg, '.');
      if (!eq || !dot || dot > eq)
        status = dv_cli_usage_error(cmd->name, "--set '%s': expected section.key=value", optarg);
      else if (dv_cli_list_push(&out->sets, optarg))
        status = dv_cli_usage_error(cmd->name, "out of memory");
    } else if (c == QUIET_ID) {
      out->quiet = 1;
    } else if (c == ':') {
      status = dv_cli_usage_error(cmd->name, "%s needs a value", argv[optind - 1]);
    } else if (c == '?') {
      status = dv_cli_usage_error(cmd->name, "unknown option '%s'", argv[optind - 1]);
    } else if (cmd->options[c].kind != DV_CLI_FLAG && cmd->options[c].kind != DV_CLI_LIST &&
               given[c]++) {
      /* one value: a second would silently replace the first */
      status = dv_cli_usage_error(cmd->name, "--%s given twice", cmd->options[c].name);
    } else if (take(cmd, &cmd->options[c], optarg)) {
      status = DV_EXIT_ERROR;
    }
  }
  free(longs);
  free(given);
  /* getopt_long has moved the positional arguments to the end */
  for (; status == DV_CLI_RUN && optind < argc; optind++)
    if (dv_cli_list_push(&out->args, argv[optind]))
      status = dv_cli_usage_error(cmd->name, "out of memory");
  if (status == DV_CLI_RUN && out->args.n < cmd->min_args)
    status = dv_cli_usage_error(cmd->name, "%s",
                                cmd->min_args == 1 ? "no scenario given" : "too few arguments");
  if (status == DV_CLI_RUN && out->args.n > cmd->max_args)
    status =
        dv_cli_usage_error(cmd->name, "unexpected argument '%s'", out->args.items[cmd->max_args]);
  if (status != DV_CLI_RUN) dv_cli_args_free(cmd, out);
  return status;
}

void dv_cli_args_free(const dv_cli_command *cmd, dv_cli_args *out) {
  free(out->sets.items);
  free(out->args.items);
  memset(out, 0, sizeof *out);
  for (size_t i = 0; i < cmd->noptions; i++)
    if (cmd->options[i].kind == DV_CLI_LIST) {
      dv_cli_list *l = cmd->options[i].value;
      free(l->items);
      memset(l, 0, sizeof *l);
    }
}

int dv_cli_default_jobs(void) {
  const long n = sysconf(_SC_NPROCESSORS_ONLN);
  return n < 1 ? 1 : n > 1024 ? 1024 : (int)n;
}
