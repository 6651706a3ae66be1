/* yaml_tree.h - a YAML document as a tree of nodes that remember where they
 * were written. Aliases share the node of their anchor (never copies), so
 * a hostile file cannot grow memory by aliasing, and what they would add if
 * copied out is counted and bounded while parsing, so that any walk over
 * the tree is bounded by the file's size and that limit. The items of the
 * root's list of objects can be read as they are parsed, and given back
 * (ystream). */
#ifndef GLINT_SCENEFILE_YAML_TREE_H
#define GLINT_SCENEFILE_YAML_TREE_H

#include <stdbool.h>
#include <stddef.h>
#include "core/arena.h"
#include "glint.h"

typedef enum ynode_kind { YNODE_SCALAR, YNODE_SEQUENCE, YNODE_MAPPING } ynode_kind;

typedef struct ynode {
    const char *file;          /* the document's name, for messages */
    char *value;               /* scalar text, NUL-terminated */
    struct ynode **items;      /* sequence: items; mapping: key, value, key, value... */
    char *note;                /* or NULL: what any problem at this node really is
                                  ("'#' starts a comment..."), said instead */
    int line, column;          /* 1-based position of the node's start */
    int count;                 /* entries in items */
    int expanded;              /* nodes in the subtree with every alias in it
                                  copied out, this one counted; at most INT_MAX */
    unsigned char kind;        /* a ynode_kind */
    bool quoted;               /* scalar written in quotes or as a block */
    bool complete;             /* the node's end has been read */
} ynode;

/* An anchor (&name) and the node it names; or an alias (*name) that named
 * no anchor before it, and the empty node that stands in its place. */
typedef struct yanchor {
    char *name;
    ynode *node;
} yanchor;

typedef struct ydoc {
    char *name;
    ynode *root;               /* NULL for an empty document */
    arena mem;                 /* every node, value and list of items */
    long node_count;           /* nodes held: a streamed list's items given
                                  back (ystream) no longer count */
    yanchor *anchors;          /* every anchor, in the order of the file */
    int anchor_count;
    size_t anchor_cap;
    yanchor *unknown;          /* aliases to no anchor before them, in order */
    int unknown_count;
    size_t unknown_cap;
} ydoc;

/* The nodes a scene's aliases may add, all its files together: an alias is
 * a copy of the node it names, and nested aliases multiply ("a billion
 * laughs"). The file's own nodes do not count. */
#define YAML_MAX_ALIAS_NODES 1000000L

/* Hooks that read the list under one key of the root mapping item by item
 * while the document is parsed, each item's nodes given back once it is
 * read: the tree of a list of a million objects never exists whole. Only
 * the first such list is streamed, and only when it has no anchor of its
 * own; any other document is parsed whole, as without hooks. */
typedef struct ystream {
    const char *key;           /* the root mapping's key: "objects" */
    /* The list starts. root is the root mapping so far: every pair before
     * the key, complete, then the key and the list, still empty; its list
     * of items is good during the call only. False stops the parse. */
    bool (*begin)(void *user, const ynode *root);
    /* An item of the list is complete. Once the call returns, its nodes
     * are given back, unless something outside it points into them: an
     * anchor it defines (a later alias may name it) or an alias in it to
     * no anchor (doc->unknown); it is never in the list's items. False
     * stops the parse. */
    bool (*item)(void *user, const ynode *item);
    void *user;
} ystream;

/* Parses `size` bytes of YAML named `name` into doc. On a syntax error
 * returns GLINT_ERR_INVALID with err holding "name:line:column: message",
 * in plain words for a tab in the indentation and for a colour that a '#'
 * made a comment of. An empty value that such a comment hid gets a note.
 * An alias to no anchor before it is not an error here but listed in
 * doc->unknown, so that the caller can say where the anchor is (another
 * file, later in this one): a document with such aliases is not a scene.
 * *alias_nodes counts the nodes the aliases of every document of a scene
 * add (each alias adds the size of the node it names, aliases in it copied
 * out); this document's are added as they are read, also while a hook reads
 * another document, and one that takes the count past YAML_MAX_ALIAS_NODES
 * is an error at the alias: "scene too large after alias expansion (limit
 * 1000000 nodes)". A parse that fails leaves *alias_nodes as it found it.
 * With `stream` (or NULL), that list is read by its hooks as it is
 * parsed; a hook that returns false, or a key of the root mapping after
 * the streamed list (its reader has read the root before the list), stops
 * the parse with GLINT_ERR_CANCELLED. */
glint_status ydoc_parse(ydoc *doc, const char *data, size_t size, const char *name, long *alias_nodes,
                        const ystream *stream, glint_error *err);

/* Whether ydoc_parse reads the text it can with yaml_quick.h's reader
 * (the default) or all of it with libyaml: tests and the fuzzer compare
 * the two. */
void ydoc_use_quick_reader(bool on);

/* Whether the trees at a and b (either may be NULL) are the same node for
 * node: kinds, values, quoting, notes, lines and columns. */
bool ynode_same(const ynode *a, const ynode *b);

/* Frees every node of the document. */
void ydoc_free(ydoc *doc);

/* Number of key-value pairs of a mapping node. */
static inline int ynode_pairs(const ynode *n) { return n->count / 2; }

/* A short noun for a node's kind, for messages: "a number", "a list", ... */
const char *ynode_describe(const ynode *n);

#endif
