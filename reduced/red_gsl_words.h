/* red_gsl_words: what a GSL status means, in words for the user.
 *
 * gsl_strerror speaks to GSL's caller ("invalid argument supplied by user"
 * is about diskval's call, not about anything the user wrote), so no message
 * passes it on: every GSL status that reaches a message goes through here. */
#ifndef RED_GSL_WORDS_H
#define RED_GSL_WORDS_H

/* what went wrong, e.g. "no sign change between the ends of the interval searched" */
const char *red_gsl_words(int status);

#endif
