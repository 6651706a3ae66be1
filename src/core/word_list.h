/* word_list.h - a list of words as a message writes it: "a, b or c". */
#ifndef GLINT_CORE_WORD_LIST_H
#define GLINT_CORE_WORD_LIST_H

#include <stddef.h>

/* Appends word, the index-th (from 0) of count words, to the text in buf
 * (size bytes, NUL-terminated): after ", ", or " or " when it is the last.
 * What does not fit is cut off. */
void word_list_append(char *buf, size_t size, const char *word, int index, int count);

#endif
