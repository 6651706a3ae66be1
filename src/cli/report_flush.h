/* report_flush.h - writing out a report on stdout as it goes, and
 * remembering why it could not be: what cli_reported (reports.h) needs to
 * say why a report was lost, apart so that the flag parser's help, which
 * the fuzzer links without the rest of the command, can use it too. */
#ifndef GLINT_CLI_REPORT_FLUSH_H
#define GLINT_CLI_REPORT_FLUSH_H

/* Writes out what a report has put on stdout so far, remembering why if
 * it cannot. A report longer than stdout's buffer calls it before the
 * buffer fills: a write that fails inside printf or fputs leaves no
 * reason behind. */
void cli_flush_report(void);

/* Why the first flush of a report to stdout failed (an errno), or 0. */
int cli_report_errno(void);

#endif
