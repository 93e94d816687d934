// SPDX-License-Identifier: MIT
// Number and vector formatting for POV-Ray SDL: shortest text that reads back to the same double.
#pragma once

#include <string>
#include <string_view>

#include "core/math/mat4.h"
#include "core/math/rgb.h"
#include "core/math/vec3.h"

namespace rt::pov {

/// Shortest decimal that round-trips to `v` (std::to_chars); -0 is written as 0.
std::string num(double v);
/// <x, y, z>
std::string vec(const Vec3 &v);
/// rgb <r, g, b>
std::string rgb(const Rgb &c);
/// POV-Ray's `matrix <...>` for a column-vector affine matrix (docs/design/povray-semantics.md
/// section 10.2): the 12 numbers are the rows of its 4x3 transpose.
std::string matrix(const Mat4 &m);
/// The shortest exact POV-Ray transform for m: `translate <...>` for a pure translation,
/// `scale <...>` for a pure axis scale, otherwise `matrix <...>`.
std::string transform(const Mat4 &m);

/// Any text (a file name, a glTF mesh name) made safe inside a `//` comment of SDL: printable
/// ASCII is kept except `\`, `*` and `/` next to each other (no `/*` or `*/`); every other
/// byte (newlines and other control characters, non-ASCII and non-UTF-8 bytes) is written
/// as `\xNN`. So nothing written into a comment can end it and reach POV-Ray's parser. The
/// one function every user-supplied string in the exporter goes through.
std::string commentText(std::string_view text);

/// A name for a file scadray writes beside the .pov (a texture): letters, digits, `.`, `-`
/// and `_`; every other byte becomes `_`, so the name is safe in an SDL string and an .ini.
std::string safeFileName(std::string_view name);

/// Whether a file name may be written as an .ini value: no control characters (a newline
/// would start a new option, such as a shell-out command), no `;` (a comment) and no `"`
/// (the quotes iniValue puts around a name).
bool iniSafe(std::string_view value);

/// A file name as an .ini value: as it is when it holds only letters, digits and `_-./`, else
/// in double quotes, since POV-Ray cuts an unquoted value at a space. `name` must be iniSafe.
std::string iniValue(const std::string &name);

/// The file name an .ini value names: iniValue undone.
std::string iniFileName(const std::string &value);

/// Checks SDL before POV-Ray runs it, as POV-Ray's tokenizer reads it (`//` and nested `/* */`
/// comments, strings with `\` escapes): the code may use only the directives the exporter
/// writes (`#version`, `#declare`), never file I/O (`#fopen`, `#read`, `#write`, `#include`),
/// macros or anything else. Returns "" when the text is acceptable, otherwise the problem with
/// its line number. A second line of defence behind commentText: POV-Ray's own I/O
/// restrictions cannot be narrowed below the system povray.conf (Debian's allows /tmp).
std::string sdlDirectiveProblem(std::string_view sdl);

}  // namespace rt::pov
