// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's text pipeline over the same libraries it links (fontconfig, FreeType,
// HarfBuzz): FontCache (font lookup), FreetypeRenderer (shaping, alignment) and
// DrawingCallback (outline flattening), so that the points come out as OpenSCAD's do.
#include "importers/scad/geometry2d/text_render.h"

#include "core/system/utf8.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_IDS_H
#include <hb-ft.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

namespace rt::scad::text {

namespace {

/// FontCache::DEFAULT_FONT, used for an empty (or blank) font name.
constexpr const char *kDefaultFont = "Liberation Sans:style=Regular";

/// fontconfig's generic family names, which match some installed font by design.
bool isGenericFamily(const std::string &family) {
    static const char *kGeneric[] = {"sans-serif", "sans",    "serif",   "monospace",
                                     "mono",       "cursive", "fantasy", "system-ui",
                                     "emoji",      "math",    "fangsong"};
    for (const char *g : kGeneric)
        if (strcasecmp(family.c_str(), g) == 0) return true;
    return false;
}

std::string trimmed(const std::string &s) {
    size_t b = s.find_first_not_of(" \t\r\n\f\v"), e = s.find_last_not_of(" \t\r\n\f\v");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// The process's fontconfig configuration and FreeType library, as OpenSCAD's FontCache
/// singleton keeps them; every use holds the mutex (neither library is thread-safe here).
class FontLibrary {
  public:
    static FontLibrary &instance() {
        static FontLibrary lib;
        return lib;
    }
    std::mutex mutex;

    bool ok() const { return ok_; }
    const std::string &initError() const { return initError_; }

    /// FontCache::register_font_file: a font file joins the application fonts (once).
    void registerFile(const std::string &path, std::vector<TextMessage> &messages) {
        if (!ok_ || !registered_.insert(path).second) return;
        if (!FcConfigAppFontAddFile(config_, reinterpret_cast<const FcChar8 *>(path.c_str())))
            messages.push_back({"Can't register font '" + path + "'"});
        // A face found before may no longer be fontconfig's best match
        clearFaces();
    }

    /// FontCache::get_font: the face fontconfig matches best (cached by name), with a
    /// scadray-only message, each time, when the requested family is not installed at all.
    FT_Face face(const std::string &font, std::vector<TextMessage> &messages) {
        auto it = faces_.find(font);
        if (it == faces_.end()) {
            std::string name = trimmed(font);
            Face f = findFace(name.empty() ? std::string(kDefaultFont) : name, messages);
            if (!f.face) return nullptr;
            it = faces_.emplace(font, std::move(f)).first;
        }
        if (!it->second.fallback.empty()) messages.push_back({it->second.fallback, true, kFontArg});
        return it->second.face;
    }

  private:
    FontLibrary() {
        // FontCache(): the configuration, plus ~/.fonts and OPENSCAD_FONT_PATH's folders
        config_ = FcInitLoadConfig();
        if (!config_) {
            initError_ = "Can't initialize fontconfig library, text() objects will not be rendered";
            return;
        }
        if (const char *home = std::getenv("HOME")) addFontDir(std::string(home) + "/.fonts");
        if (const char *env = std::getenv("OPENSCAD_FONT_PATH")) {
            std::stringstream paths(env);
            std::string dir;
            while (std::getline(paths, dir, ':'))
                if (!dir.empty()) addFontDir(std::filesystem::absolute(dir).string());
        }
        FcConfigBuildFonts(config_);
        if (FT_Init_FreeType(&library_) != 0) {
            initError_ = "Can't initialize freetype library, text() objects will not be rendered";
            return;
        }
        ok_ = true;
    }
    ~FontLibrary() {
        clearFaces();
        if (library_) FT_Done_FreeType(library_);
        if (config_) FcConfigDestroy(config_);
    }

    void addFontDir(const std::string &path) {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            FcConfigAppFontAddDir(config_, reinterpret_cast<const FcChar8 *>(path.c_str()));
    }

    /// A face found for a font name, and the message when it is only a fallback.
    struct Face {
        FT_Face face = nullptr;
        std::string fallback;
    };

    void clearFaces() {
        for (auto &[name, f] : faces_) FT_Done_Face(f.face);
        faces_.clear();
    }

    /// FontCache::init_pattern: outline, scalable fonts only.
    static void initPattern(FcPattern *pattern) {
        FcPatternAddBool(pattern, FC_OUTLINE, FcTrue);
        FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);
    }

    /// Whether any installed outline font has the family the pattern names first.
    bool familyInstalled(const std::string &family) {
        FcPattern *p = FcPatternCreate();
        FcPatternAddString(p, FC_FAMILY, reinterpret_cast<const FcChar8 *>(family.c_str()));
        initPattern(p);
        FcObjectSet *os = FcObjectSetBuild(FC_FAMILY, nullptr);
        FcFontSet *set = FcFontList(config_, p, os);
        bool found = set && set->nfont > 0;
        if (set) FcFontSetDestroy(set);
        FcObjectSetDestroy(os);
        FcPatternDestroy(p);
        return found;
    }

    /// FontCache::try_charmap.
    static bool tryCharmap(FT_Face face, int platform, int encoding) {
        for (int i = 0; i < face->num_charmaps; ++i) {
            FT_CharMap cm = face->charmaps[i];
            if (cm->platform_id == platform && (encoding < 0 || cm->encoding_id == encoding) &&
                FT_Set_Charmap(face, cm) == 0)
                return true;
        }
        return false;
    }

    /// FontCache::find_face_fontconfig.
    Face findFace(const std::string &font, std::vector<TextMessage> &messages) {
        FcPattern *pattern = FcNameParse(reinterpret_cast<const FcChar8 *>(font.c_str()));
        if (!pattern) {
            messages.push_back({"font '" + font +
                                    "' is not a fontconfig pattern (OpenSCAD 2021.01 crashes "
                                    "on it); no text",
                                true, kFontArg});
            return {};
        }
        FcChar8 *family = nullptr;
        std::string requested;
        if (FcPatternGetString(pattern, FC_FAMILY, 0, &family) == FcResultMatch)
            requested = reinterpret_cast<const char *>(family);
        initPattern(pattern);
        FcConfigSubstitute(config_, pattern, FcMatchPattern);
        FcDefaultSubstitute(pattern);
        FcResult result;
        FcPattern *match = FcFontMatch(config_, pattern, &result);
        FcPatternDestroy(pattern);
        FcChar8 *file = nullptr;
        int index = 0;
        if (!match || FcPatternGetString(match, FC_FILE, 0, &file) != FcResultMatch ||
            FcPatternGetInteger(match, FC_INDEX, 0, &index) != FcResultMatch) {
            if (match) FcPatternDestroy(match);
            return {};
        }
        FT_Face face = nullptr;
        FT_Error error = FT_New_Face(library_, reinterpret_cast<const char *>(file), index, &face);
        FcPatternDestroy(match);
        if (error) return {};

        // A family that is not installed: OpenSCAD silently takes fontconfig's best match
        Face found{face, ""};
        if (!requested.empty() && !isGenericFamily(requested) && !familyInstalled(requested))
            found.fallback = "font '" + font + "' is not installed; fontconfig's best match, " +
                             std::string(face->family_name ? face->family_name : "?") +
                             ":style=" + (face->style_name ? face->style_name : "?") +
                             ", is used as OpenSCAD 2021.01 uses it";

        // The Unicode charmap, else the first of OpenSCAD's list of alternatives
        if (FT_Select_Charmap(face, FT_ENCODING_UNICODE) != 0) {
            bool set = tryCharmap(face, TT_PLATFORM_MICROSOFT, TT_MS_ID_UNICODE_CS) ||
                       tryCharmap(face, TT_PLATFORM_ISO, TT_ISO_ID_10646) ||
                       tryCharmap(face, TT_PLATFORM_APPLE_UNICODE, -1) ||
                       tryCharmap(face, TT_PLATFORM_MICROSOFT, TT_MS_ID_SYMBOL_CS) ||
                       tryCharmap(face, TT_PLATFORM_MACINTOSH, TT_MAC_ID_ROMAN) ||
                       tryCharmap(face, TT_PLATFORM_ISO, TT_ISO_ID_8859_1) ||
                       tryCharmap(face, TT_PLATFORM_ISO, TT_ISO_ID_7BIT_ASCII);
            if (!set)
                messages.push_back({std::string("Could not select a char map for font ") +
                                        (face->family_name ? face->family_name : "?") + "/" +
                                        (face->style_name ? face->style_name : "?") + "'",
                                    false, kFontArg});
        }
        return found;
    }

    FcConfig *config_ = nullptr;
    FT_Library library_ = nullptr;
    bool ok_ = false;
    std::string initError_;
    std::map<std::string, Face> faces_;
    std::set<std::string> registered_;
};

/// FontCache::is_windows_symbol_font: a Microsoft symbol charmap whose characters sit in the
/// Private Use Area at 0xf000.
bool isWindowsSymbolFont(FT_Face face) {
    if (!face->charmap || face->charmap->platform_id != TT_PLATFORM_MICROSOFT ||
        face->charmap->encoding_id != TT_MS_ID_SYMBOL_CS)
        return false;
    FT_UInt gindex = 0;
    FT_ULong charcode = FT_Get_First_Char(face, &gindex);
    return gindex != 0 && charcode >= 0xf000;
}

/// FreetypeRenderer::is_ignored_script.
bool isIgnoredScript(hb_script_t s) {
    return s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN ||
           s == HB_SCRIPT_INVALID;
}

/// DrawingCallback: outline points in units of the font scale, each glyph placed at its
/// offset plus the advances so far and multiplied by the size; a Bezier curve becomes
/// `segments` points at equal parameter steps. The arithmetic follows OpenSCAD's term order,
/// so the points are the same doubles.
class Flattener {
  public:
    Flattener(long segments, double size) : segments_(segments), size_(size) {}

    void startGlyph() { glyph_.clear(); }
    void setOffset(double x, double y) { offset_ = {x, y}; }
    void addAdvance(double x, double y) { advance_ = {advance_.x + x, advance_.y + y}; }
    void finishGlyph(std::vector<std::vector<Outline>> &out) {
        closeOutline();
        if (!glyph_.empty()) out.push_back(std::move(glyph_));
        glyph_.clear();
    }

    void moveTo(Vec2 to) {
        closeOutline();
        addVertex(to);
        pen_ = to;
    }
    void lineTo(Vec2 to) {
        addVertex(to);
        pen_ = to;
    }
    void conicTo(Vec2 c1, Vec2 to) {
        for (long i = 1; i <= segments_; ++i) {
            const double a = i * (1.0 / static_cast<double>(segments_));
            double p0 = std::pow(1 - a, 2), p1 = std::pow(1 - a, 1), p2 = std::pow(a, 2);
            addVertex({pen_.x * p0 + c1.x * 2 * p1 * a + to.x * p2,
                       pen_.y * p0 + c1.y * 2 * p1 * a + to.y * p2});
        }
        pen_ = to;
    }
    void cubicTo(Vec2 c1, Vec2 c2, Vec2 to) {
        for (long i = 1; i <= segments_; ++i) {
            const double a = i * (1.0 / static_cast<double>(segments_));
            double p0 = std::pow(1 - a, 3), p1 = std::pow(1 - a, 2), p2 = std::pow(1 - a, 1),
                   q2 = std::pow(a, 2), q3 = std::pow(a, 3);
            addVertex({pen_.x * p0 + c1.x * 3 * p1 * a + c2.x * 3 * p2 * q2 + to.x * q3,
                       pen_.y * p0 + c1.y * 3 * p1 * a + c2.y * 3 * p2 * q2 + to.y * q3});
        }
        pen_ = to;
    }

  private:
    void addVertex(Vec2 v) {
        outline_.push_back(
            {size_ * (v.x + offset_.x + advance_.x), size_ * (v.y + offset_.y + advance_.y)});
    }
    void closeOutline() {
        if (!outline_.empty()) glyph_.push_back(std::move(outline_));
        outline_.clear();
    }

    long segments_;
    double size_;
    Vec2 pen_, offset_, advance_;
    Outline outline_;
    std::vector<Outline> glyph_;
};

Vec2 scaled(const FT_Vector *v) {
    return {static_cast<double>(v->x) / kFontScale, static_cast<double>(v->y) / kFontScale};
}

/// FT_Outline_Decompose's callbacks into a Flattener.
struct Decomposer {
    static int moveTo(const FT_Vector *to, void *u) {
        static_cast<Flattener *>(u)->moveTo(scaled(to));
        return 0;
    }
    static int lineTo(const FT_Vector *to, void *u) {
        static_cast<Flattener *>(u)->lineTo(scaled(to));
        return 0;
    }
    static int conicTo(const FT_Vector *c, const FT_Vector *to, void *u) {
        static_cast<Flattener *>(u)->conicTo(scaled(c), scaled(to));
        return 0;
    }
    static int cubicTo(const FT_Vector *c1, const FT_Vector *c2, const FT_Vector *to, void *u) {
        static_cast<Flattener *>(u)->cubicTo(scaled(c1), scaled(c2), scaled(to));
        return 0;
    }
};

/// FT_Outline_Decompose's callbacks counting the points a Flattener would make.
struct PointCounter {
    long segments;
    size_t points = 0;
    static int point(const FT_Vector *, void *u) {
        ++static_cast<PointCounter *>(u)->points;
        return 0;
    }
    static int conic(const FT_Vector *, const FT_Vector *, void *u) {
        auto *c = static_cast<PointCounter *>(u);
        c->points += static_cast<size_t>(c->segments);
        return 0;
    }
    static int cubic(const FT_Vector *, const FT_Vector *, const FT_Vector *, void *u) {
        return conic(nullptr, nullptr, u);
    }
};

/// FreetypeRenderer::calc_x_offset.
double xOffset(const std::string &halign, double width, std::vector<TextMessage> &messages) {
    if (halign == "right") return -width;
    if (halign == "center") return -width / 2.0;
    if (halign != "left")
        messages.push_back(
            {"Unknown value for the halign parameter (use \"left\", \"right\" or "
             "\"center\"): '" +
                 halign + "'",
             false, kHalignArg});
    return 0;
}

/// FreetypeRenderer::calc_y_offset.
double yOffset(const std::string &valign, double ascend, double descend,
               std::vector<TextMessage> &messages) {
    if (valign == "top") return -ascend;
    if (valign == "center") return descend / 2.0 - ascend / 2.0;
    if (valign == "bottom") return descend;
    if (valign != "baseline")
        messages.push_back(
            {"Unknown value for the valign parameter (use \"baseline\", \"bottom\", "
             "\"top\" or \"center\"): '" +
                 valign + "'",
             false, kValignArg});
    return 0;
}

/// Glyph advances, offsets and grid-fitted boxes (26.6 pixel units) in units of the size:
/// OpenSCAD divides them by kPositionScale, 1.024 times the outlines' kFontScale, so they are
/// 1000/1024 of the outline unit [verified against the 2021.01 binary: "II", "AV" with
/// halign="right", valign="top" and "gO" centred agree to the SVG export's 6 digits, and
/// dividing by kFontScale misplaces glyphs by 2 %].
double hbUnits(double v) { return v / kPositionScale; }

struct HbBuffer {
    hb_buffer_t *b = hb_buffer_create();
    ~HbBuffer() { hb_buffer_destroy(b); }
};

}  // namespace

void detectProperties(TextParams &p) {
    // The script given, else the one script of all characters that have one (Unknown when
    // they disagree, Invalid when none has one)
    hb_script_t script = hb_script_from_string(p.script.c_str(), -1);
    if (script == HB_SCRIPT_INVALID) {
        HbBuffer buf;
        int len = static_cast<int>(std::strlen(p.text.c_str()));
        hb_buffer_add_utf8(buf.b, p.text.c_str(), len, 0, len);
        unsigned int count = 0;
        hb_glyph_info_t *info = hb_buffer_get_glyph_infos(buf.b, &count);
        for (unsigned int i = 0; i < count; ++i) {
            hb_script_t s = hb_unicode_script(hb_unicode_funcs_get_default(), info[i].codepoint);
            if (isIgnoredScript(s)) continue;
            if (script == HB_SCRIPT_INVALID)
                script = s;
            else if (script != s && script != HB_SCRIPT_UNKNOWN)
                script = HB_SCRIPT_UNKNOWN;
        }
    }
    if (!isIgnoredScript(script)) {
        char tag[5] = {};
        hb_tag_to_string(hb_script_to_iso15924_tag(script), tag);
        p.script = tag;
    }
    hb_direction_t direction = hb_direction_from_string(p.direction.c_str(), -1);
    if (direction == HB_DIRECTION_INVALID) direction = hb_script_get_horizontal_direction(script);
    p.direction = hb_direction_to_string(direction);
}

TextResult renderText(const TextParams &p, const std::vector<std::string> &fontFiles) {
    TextResult r;
    FontLibrary &lib = FontLibrary::instance();
    std::lock_guard<std::mutex> lock(lib.mutex);
    if (!lib.ok()) {
        r.messages.push_back({lib.initError()});
        return r;
    }
    for (const std::string &f : fontFiles) lib.registerFile(f, r.messages);
    FT_Face face = lib.face(p.font, r.messages);
    if (!face) return r;
    r.fontUsed = std::string(face->family_name ? face->family_name : "") +
                 ":style=" + (face->style_name ? face->style_name : "");
    if (FT_Set_Char_Size(face, 0, static_cast<FT_F26Dot6>(kFontScale), 100, 100) != 0) {
        r.messages.push_back({"Can't set font size for font " + p.font, false, kFontArg});
        return r;
    }

    // Shape the text (a Windows symbol font maps characters below 0x100 to 0xf000 + c)
    hb_font_t *font = hb_ft_font_create(face, nullptr);
    HbBuffer buf;
    hb_buffer_set_direction(buf.b, hb_direction_from_string(p.direction.c_str(), -1));
    hb_buffer_set_script(buf.b, hb_script_from_string(p.script.c_str(), -1));
    hb_buffer_set_language(buf.b, hb_language_from_string(p.language.c_str(), -1));
    if (isWindowsSymbolFont(face)) {
        std::vector<long> cps;
        for (const std::string &ch : utf8Chars(p.text)) cps.push_back(utf8Decode(ch));
        if (std::find(cps.begin(), cps.end(), -1) == cps.end()) {
            for (long c : cps) {
                std::string one;
                appendUtf8(one, static_cast<unsigned>(c < 0x100 ? 0xf000 + c : c));
                hb_buffer_add_utf8(buf.b, one.c_str(), static_cast<int>(one.size()), 0,
                                   static_cast<int>(one.size()));
            }
        } else {
            r.messages.push_back(
                {"Warning: Ignoring text with invalid UTF-8 encoding: \"" + p.text + "\""});
        }
    } else {
        int len = static_cast<int>(std::strlen(p.text.c_str()));
        hb_buffer_add_utf8(buf.b, p.text.c_str(), len, 0, len);
    }
    hb_shape(font, buf.b, nullptr, 0);
    unsigned int count = 0;
    hb_glyph_info_t *info = hb_buffer_get_glyph_infos(buf.b, &count);
    hb_glyph_position_t *pos = hb_buffer_get_glyph_positions(buf.b, &count);

    // Load the glyphs (hinted, as FT_LOAD_DEFAULT does)
    struct Glyph {
        FT_Glyph glyph;
        const hb_glyph_position_t *pos;
    };
    std::vector<Glyph> glyphs;
    for (unsigned int i = 0; i < count; ++i) {
        FT_UInt index = info[i].codepoint;
        FT_Glyph g = nullptr;
        if (FT_Load_Glyph(face, index, FT_LOAD_DEFAULT) != 0) {
            r.messages.push_back({"Could not load glyph " + std::to_string(index) +
                                  " for char at index " + std::to_string(i) + " in text '" +
                                  p.text + "'"});
            continue;
        }
        if (FT_Get_Glyph(face->glyph, &g) != 0) {
            r.messages.push_back({"Could not get glyph " + std::to_string(index) +
                                  " for char at index " + std::to_string(i) + " in text '" +
                                  p.text + "'"});
            continue;
        }
        if (g->format != FT_GLYPH_FORMAT_OUTLINE) {
            r.messages.push_back({"glyph " + std::to_string(index) + " of text '" + p.text +
                                      "' has no outline; left out",
                                  true});
            FT_Done_Glyph(g);
            continue;
        }
        glyphs.push_back({g, &pos[i]});
    }

    // The extent that halign and valign align: advances along the direction, grid-fitted
    // boxes across it
    bool horizontal = HB_DIRECTION_IS_HORIZONTAL(hb_buffer_get_direction(buf.b));
    double width = 0, ascend = 0, descend = 0;
    for (const Glyph &g : glyphs) {
        FT_BBox box;
        FT_Glyph_Get_CBox(g.glyph, FT_GLYPH_BBOX_GRIDFIT, &box);
        if (horizontal) {
            width += hbUnits(g.pos->x_advance) * p.spacing;
            ascend = std::max(ascend, std::max(0.0, hbUnits(box.yMax)));
            descend = std::max(descend, std::max(0.0, -hbUnits(box.yMin)));
        } else {
            width = std::max(width, hbUnits(box.xMax - box.xMin));
            ascend += hbUnits(g.pos->y_advance) * p.spacing;
        }
    }
    double x0 = xOffset(p.halign, width, r.messages);
    double y0 = yOffset(p.valign, ascend, descend, r.messages);

    // The points the outlines will have, counted first so that a huge $fn is refused
    FT_Outline_Funcs counting{};
    counting.move_to = &PointCounter::point;
    counting.line_to = &PointCounter::point;
    counting.conic_to = &PointCounter::conic;
    counting.cubic_to = &PointCounter::cubic;
    PointCounter counter{p.segments};
    for (const Glyph &g : glyphs)
        FT_Outline_Decompose(&reinterpret_cast<FT_OutlineGlyph>(g.glyph)->outline, &counting,
                             &counter);
    r.points = counter.points;

    // Each glyph's outline, flattened
    if (counter.points <= kMaxTextPoints) {
        Flattener flat(p.segments, p.size);
        FT_Outline_Funcs funcs{};
        funcs.move_to = &Decomposer::moveTo;
        funcs.line_to = &Decomposer::lineTo;
        funcs.conic_to = &Decomposer::conicTo;
        funcs.cubic_to = &Decomposer::cubicTo;
        for (const Glyph &g : glyphs) {
            flat.startGlyph();
            flat.setOffset(x0 + hbUnits(g.pos->x_offset), y0 + hbUnits(g.pos->y_offset));
            FT_Outline_Decompose(&reinterpret_cast<FT_OutlineGlyph>(g.glyph)->outline, &funcs,
                                 &flat);
            flat.addAdvance(hbUnits(g.pos->x_advance) * p.spacing,
                            hbUnits(g.pos->y_advance) * p.spacing);
            flat.finishGlyph(r.glyphs);
        }
    }
    for (Glyph &g : glyphs) FT_Done_Glyph(g.glyph);
    hb_font_destroy(font);
    return r;
}

}  // namespace rt::scad::text
