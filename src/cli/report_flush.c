/* report_flush.c - a report on stdout written out as it goes, and why it
 * could not be (report_flush.h). */
#include <errno.h>
#include <stdio.h>
#include "cli/report_flush.h"

/* Why the first flush of a report to stdout failed, or 0: a stream that
 * failed once may flush its next buffer without error, and errno is gone. */
static int report_errno;

void cli_flush_report(void)
{
    errno = 0;
    if (fflush(stdout) != 0 && !report_errno)
        report_errno = errno ? errno : EIO;
}

int cli_report_errno(void)
{
    return report_errno;
}
