#pragma once
/// \file
/// The version of termpool: of the program, the library and the Python module. It lives here
/// only; the Makefile reads it for the library's file names and termpool.pc, and `termpool
/// --version` prints it.

/// Major version: raised when the library's interface changes incompatibly (from 1.0 on).
#define TERMPOOL_VERSION_MAJOR 0
/// Minor version: new features; below 1.0 it may also change the interface, so the shared
/// library's soname carries it (libtermpool.so.0.2).
#define TERMPOOL_VERSION_MINOR 2
/// Patch version: fixes only.
#define TERMPOOL_VERSION_PATCH 0

/// The version as text, "MAJOR.MINOR.PATCH".
#define TERMPOOL_VERSION                                                                           \
    TERMPOOL_VERSION_TEXT_(TERMPOOL_VERSION_MAJOR)                                                 \
    "." TERMPOOL_VERSION_TEXT_(TERMPOOL_VERSION_MINOR) "." TERMPOOL_VERSION_TEXT_(                 \
        TERMPOOL_VERSION_PATCH)
/// One number as text (the two steps let a macro's value, not its name, be quoted).
#define TERMPOOL_VERSION_TEXT_(number) TERMPOOL_VERSION_QUOTE_(number)
/// Quotes its argument.
#define TERMPOOL_VERSION_QUOTE_(text) #text
