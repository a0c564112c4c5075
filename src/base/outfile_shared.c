/* outfile_shared.c: what all-or-nothing output files do alike on every system
 * (see outfile.h; the systems' own calls are in outfile_posix.c and
 * outfile_win32.c). */
#include "outfile_sys.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "base/file.h"

int outfile_remove_temp(OutFile *out, Error *err)
{
    int saved = out->temp[0] ? file_delete(out->temp) : 0;

    if (saved != 0 && err) {
        size_t n = strlen(err->message);
        snprintf(err->message + n, sizeof err->message - n,
                 "; and the temporary file '%s' could not be removed (%s): delete it", out->temp,
                 strerror(saved));
    }
    out->temp[0] = '\0';
    return saved != 0 ? -1 : 0;
}

int outfile_failed(OutFile *out, int saved, Error *err)
{
    error_set(err, out->is_stdout ? "<stdout>" : out->path, "cannot write the image: %s",
              strerror(saved ? saved : EIO));
    outfile_remove_temp(out, err);
    return -1;
}

int outfile_abort(OutFile *out, Error *err)
{
    /* An unnamed file (Linux's) vanishes with its descriptor. */
    if (out->fp && !out->is_stdout)
        fclose(out->fp);
    out->fp = NULL;
    return outfile_remove_temp(out, err);
}
