/* word_list.c - a list of words as a message writes it: "a, b or c". */
#include <stdio.h>
#include <string.h>
#include "core/word_list.h"

void word_list_append(char *buf, size_t size, const char *word, int index, int count)
{
    size_t used = strlen(buf);
    const char *separator = index == 0 ? "" : index == count - 1 ? " or " : ", ";
    snprintf(buf + used, size - used, "%s%s", separator, word);
}
