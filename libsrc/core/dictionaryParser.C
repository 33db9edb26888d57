/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Entry-level reading of dictionaries (syntax: docs/dictionaries.md).
// Macros are expanded while reading, as OpenFOAM does, so a $name
// sees the entries written before it (in this dictionary or its parents).

#include "dictionaryParser.H"
#include "error.H"
#include "formatting.H"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace sphvcpm
{

namespace
{

// Deep enough for any sane case, shallow enough to stop a runaway chain of
// distinct files (a cycle is caught directly).
constexpr std::size_t maxIncludeDepth = 32;

// Paths made of an #include's name are quoted in full up to this length
// (beyond any real one), clipped beyond: the name may be a runaway string.
constexpr std::size_t maxPathShown = 1024;

// Nesting limits that keep the recursive reader off the end of the stack
// whatever the input.
constexpr int maxDictDepth = 256;
constexpr int maxNameDepth = 32;

// A value grown past this by $macros (each doubling the last) is an error,
// not an out-of-memory.
constexpr std::size_t maxValueTokens = 10000000;

using dictionaryDetail::clip;

const std::vector<std::string> supportedDirectives =
{
    "#include", "#includeIfPresent", "#sinclude", "#includeEtc", "#remove",
    "#inputMode"
};

bool isIncludeDirective(const std::string& name)
{
    return name == "include" || name == "includeIfPresent"
        || name == "sinclude" || name == "includeEtc";
}

bool isKnownDirective(const std::string& name)
{
    return isIncludeDirective(name) || name == "remove"
        || name == "inputMode";
}

[[noreturn]] void refuseDirective(const std::string& name,
                                  const std::string& file, int line)
{
    std::string why;
    if (name == "calc" || name == "codeStream")
    {
        why = ": it compiles and runs C++ code while reading; write the "
              "value itself instead.";
    }
    else if (name == "if" || name == "ifeq" || name == "ifneq"
          || name == "else" || name == "elif" || name == "endif")
    {
        why = ": conditional input is not supported; write only the "
              "entries that apply.";
    }
    else if (name == "includeFunc" || name == "includeFunction"
          || name == "includeModel")
    {
        why = ": write the function in the functions sub-dictionary of "
              "controlDict.";
    }
    else
    {
        why = ".";
    }
    fatalIOError(file, line, "Directive #" + clip(name)
        + " is not supported by sphvcpm" + why + " Supported directives "
        "are " + str(supportedDirectives),
        "#" + name);
}

std::string foundText(bool have, const token& t)
{
    return have ? dictionaryDetail::describe(t) : "end of file";
}

// How a macro name is looked up in one dictionary.
struct lookupMode
{
    bool recursive;
    bool patterns;
};

const entry* findHere(const dictionary* d, const std::string& key,
                      bool patterns)
{
    const entry* e = d->findEntry(key);
    // findEntry tries the exact keyword first: a pattern match means no
    // literal one.
    return e && (patterns || e->keyword() == key) ? e : nullptr;
}

const entry* findIn(const dictionary* d, const std::string& key,
                    lookupMode mode)
{
    for (; d; d = mode.recursive ? d->parent() : nullptr)
    {
        if (const entry* e = findHere(d, key, mode.patterns))
        {
            return e;
        }
    }
    return nullptr;
}

// A key that may contain dots (alpha.water) or, failing that, ESI's
// dot-scoped path a.b.c.
const entry* findDotted(const dictionary* d, const std::string& key,
                        lookupMode mode)
{
    if (key.empty())
    {
        return nullptr;
    }
    if (const entry* e = findIn(d, key, mode))
    {
        return e;
    }
    for (auto p = key.find('.'); p != std::string::npos;
         p = key.find('.', p + 1))
    {
        if (p == 0 || p + 1 >= key.size())
        {
            continue;
        }
        const entry* pe = findIn(d, key.substr(0, p), mode);
        if (pe && pe->isDict())
        {
            if (const entry* e = findDotted(&pe->dict(), key.substr(p + 1),
                                            {false, mode.patterns}))
            {
                return e;
            }
        }
    }
    return nullptr;
}

// FatalError when file exists but is not a regular file: a FIFO or a
// device would block the open or never end, a directory reads as nothing.
void checkRegularFile(const std::filesystem::path& file,
                      const std::string& errorFile, int errorLine,
                      const std::string& what)
{
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!ec && std::filesystem::exists(status)
     && !std::filesystem::is_regular_file(status))
    {
        fatalIOError(errorFile, errorLine, "Cannot read " + what + " \""
            + file.string() + "\": it is "
            + (std::filesystem::is_directory(status) ? "a directory"
               : "not a regular file (a FIFO, socket or device)"));
    }
}


std::string readWholeFile(const std::filesystem::path& file,
                          const std::string& errorFile, int errorLine,
                          const std::string& what)
{
    checkRegularFile(file, errorFile, errorLine, what);
    std::ifstream is(file, std::ios::binary);
    if (!is)
    {
        fatalIOError(errorFile, errorLine, "Cannot open " + what + " \""
            + file.string() + "\"");
    }
    std::ostringstream os;
    os << is.rdbuf();
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Public functions  * * * * * * * * * * * * //

dictionary dictionaryParser::readFile(const std::filesystem::path& file)
{
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec))
    {
        fatalIOError(file.string(), 0, "Cannot read dictionary \""
            + file.string() + "\": it is a directory");
    }
    const std::string text =
        readWholeFile(file, file.string(), 0, "dictionary file");

    dictionary dict(file.string());
    dictionaryParser parser;
    parser.includeStack_.push_back
    (
        std::filesystem::weakly_canonical(file, ec).string()
    );
    parser.parseText(dict, text, file.string(), scope::mainFile);
    return dict;
}


dictionary dictionaryParser::readString(const std::string& text,
                                        const std::string& name)
{
    dictionary dict(name);
    dictionaryParser parser;
    std::error_code ec;
    parser.includeStack_.push_back
    (
        std::filesystem::weakly_canonical(name, ec).string()
    );
    parser.parseText(dict, text, name, scope::mainFile);
    return dict;
}


void dictionaryParser::adopt(dictionary& child, const dictionary& parent,
                             const std::string& key)
{
    child.parent_ = &parent;
    child.name_ = parent.name_ + "/" + key;
    for (auto& e : child.entries_)
    {
        if (e.isDict())
        {
            adopt(e.dict(), child, e.keyword());
        }
    }
}


void dictionaryParser::add(dictionary& dict, entry&& e, inputMode mode)
{
    entry* existing = nullptr;
    for (auto& x : dict.entries_)
    {
        if (x.keyword() == e.keyword())
        {
            existing = &x;
            break;
        }
    }

    if (!existing)
    {
        dict.entries_.push_back(std::move(e));
        entry& added = dict.entries_.back();
        if (added.isDict())
        {
            adopt(added.dict(), dict, added.keyword());
        }
        return;
    }

    switch (mode)
    {
        case inputMode::merge:
        {
            if (existing->isDict() && e.isDict())
            {
                existing->markMerged(e.file(), e.line());
                dictionary& into = existing->dict();
                for (auto& sub : e.dict().entries_)
                {
                    add(into, std::move(sub), inputMode::merge);
                }
                return;
            }
            break;   // a value replaces, in place
        }
        case inputMode::overwrite:
        {
            break;
        }
        case inputMode::protect:
        {
            return;
        }
        case inputMode::warn:
        {
            warning("Duplicate keyword '" + clip(e.keyword())
                + "' in dictionary \"" + dict.name() + "\" ignored "
                "(#inputMode warn); the entry "
                "from line " + std::to_string(existing->line()) + " is kept",
                e.file(), e.line());
            return;
        }
        case inputMode::error:
        {
            fatalIOError(e.file(), e.line(), "Duplicate keyword '"
                + clip(e.keyword()) + "' in dictionary \"" + dict.name()
                + "\" (first defined at line "
                + std::to_string(existing->line()) + " of "
                + existing->file() + ") while #inputMode is error",
                e.keyword());
        }
    }

    // A variable redefined after its use stays a variable.
    const bool variable = existing->usedAsVariable();
    *existing = std::move(e);
    if (variable)
    {
        existing->markUsedAsVariable();
    }
    if (existing->isDict())
    {
        adopt(existing->dict(), dict, existing->keyword());
    }
}


const entry* dictionaryParser::findScoped(const dictionary& dict,
                                          const std::string& name,
                                          bool patterns,
                                          const dictionary** searched,
                                          std::vector<const entry*>* through)
{
    const dictionary* cur = &dict;
    bool recursive = true;
    std::string rest = name;
    if (searched)
    {
        *searched = cur;
    }

    if (!rest.empty() && (rest[0] == '!' || rest[0] == ':' || rest[0] == '^'))
    {
        cur = &dict.topDict();
        rest.erase(0, 1);
        recursive = false;
    }
    if (rest.empty())
    {
        return nullptr;
    }

    if (rest.find('/') != std::string::npos)
    {
        if (rest[0] == '/')
        {
            cur = &dict.topDict();
            recursive = false;
        }
        std::vector<std::string> parts;
        std::string part;
        std::istringstream is(rest);
        while (std::getline(is, part, '/'))
        {
            if (!part.empty())
            {
                parts.push_back(part);
            }
        }
        if (parts.empty())
        {
            return nullptr;
        }
        for (std::size_t i = 0; i + 1 < parts.size(); ++i)
        {
            if (parts[i] == "..")
            {
                cur = cur->parent();
                if (!cur)
                {
                    return nullptr;
                }
            }
            else if (parts[i] != ".")
            {
                const entry* e =
                    findIn(cur, parts[i], {recursive, patterns});
                if (!e || !e->isDict())
                {
                    if (searched)
                    {
                        *searched = cur;
                    }
                    return nullptr;
                }
                if (through)
                {
                    through->push_back(e);
                }
                cur = &e->dict();
            }
            recursive = false;
        }
        if (searched)
        {
            *searched = cur;
        }
        if (parts.back() == ".." || parts.back() == ".")
        {
            return nullptr;
        }
        return findIn(cur, parts.back(), {recursive, patterns});
    }

    if (rest[0] == '.')
    {
        // ESI: .x is x here, ..x is x in the parent, and so on.
        std::size_t n = rest.find_first_not_of('.');
        if (n == std::string::npos)
        {
            return nullptr;
        }
        for (std::size_t k = 1; k < n; ++k)
        {
            cur = cur->parent();
            if (!cur)
            {
                return nullptr;
            }
        }
        if (searched)
        {
            *searched = cur;
        }
        return findDotted(cur, rest.substr(n), {false, patterns});
    }

    if (searched)
    {
        *searched = cur;
    }
    return findDotted(cur, rest, {recursive, patterns});
}


// * * * * * * * * * * * * * * * Private functions * * * * * * * * * * * * //

void dictionaryParser::parseText(dictionary& dict, const std::string& text,
                                 const std::string& file, scope where)
{
    tokeniser tk(text, file);
    parseEntries(dict, tk, nullptr, where);
}


void dictionaryParser::parseEntries(dictionary& dict, tokeniser& tk,
                                    const token* open, scope where)
{
    token t;
    while (true)
    {
        if (!tk.read(t))
        {
            if (open)
            {
                const std::string key =
                    dict.name_.substr(dict.name_.rfind('/') + 1);
                fatalIOError(tk.file(), open->line, "Unexpected end of file "
                    "in sub-dictionary '" + clip(key) + "' opened at line "
                    + std::to_string(open->line) + ": expected '}'", key);
            }
            return;
        }

        if (t.isPunctuation('}'))
        {
            if (open)
            {
                return;
            }
            fatalIOError(tk.file(), t.line, "Unexpected '}' with no "
                "matching '{': expected a keyword or end of file");
        }
        if (t.isPunctuation(';'))
        {
            continue;   // stray semicolons are allowed
        }

        switch (t.type)
        {
            case token::kind::directive:
            {
                readDirective(dict, tk, t);
                break;
            }
            case token::kind::variable:
            {
                readKeyVariable(dict, tk, t, where);
                break;
            }
            case token::kind::word:
            case token::kind::string:
            {
                readEntry(dict, tk, t, where);
                break;
            }
            default:
            {
                std::string hint;
                if (t.isNumber() || t.isPunctuation('('))
                {
                    hint = " (lists of anonymous entries are not supported)";
                }
                fatalIOError(tk.file(), t.line, "Expected a keyword, found "
                    + dictionaryDetail::describe(t) + hint);
            }
        }
    }
}


void dictionaryParser::readEntry(dictionary& dict, tokeniser& tk,
                                 const token& keyTok, scope where)
{
    const std::string key = keyTok.text;
    const bool isPattern = keyTok.type == token::kind::string;
    if (isPattern)
    {
        // std::regex compiles and matches by recursion: a pattern of tens
        // of thousands of characters overflows the stack instead of failing.
        constexpr std::size_t maxPatternLength = 1000;
        if (key.size() > maxPatternLength)
        {
            fatalIOError(tk.file(), keyTok.line, "A quoted keyword is a"
                " regular expression; this one \"" + clip(key) + "\" has "
                + std::to_string(key.size()) + " characters, more than the "
                + std::to_string(maxPatternLength) + " allowed", key);
        }
        try
        {
            dictionaryDetail::checkRegex(key);
        }
        catch (const std::regex_error& err)
        {
            fatalIOError(tk.file(), keyTok.line, "Invalid regular "
                "expression \"" + clip(key) + "\" as keyword: " + err.what(),
                key);
        }
    }

    token next;
    if (!tk.peek(next))
    {
        fatalIOError(tk.file(), keyTok.line, "Unexpected end of file after "
            "keyword '" + clip(key) + "': expected a value and ';', or '{'",
            key);
    }

    if (next.isPunctuation('{'))
    {
        tk.read(next);
        if (depth_ >= maxDictDepth)
        {
            fatalIOError(tk.file(), next.line, "Sub-dictionary '" + clip(key)
                + "' nested more than " + std::to_string(maxDictDepth)
                + " levels deep", key);
        }
        auto sub = std::make_unique<dictionary>(dict.name_ + "/" + key);
        sub->file_ = tk.file();
        sub->line_ = next.line;
        sub->parent_ = &dict;
        ++depth_;
        parseEntries(*sub, tk, &next, scope::subDict);
        --depth_;

        if (where != scope::subDict && key == "FoamFile" && !isPattern)
        {
            // Only field files act on the format, but a typo in it is an
            // error in any file (OpenFOAM's default, ascii, when absent).
            sub->getWordOrDefault("format", {"ascii", "binary"}, "ascii");

            // The header of the main file is kept aside; those of
            // included files are dropped.
            if (where == scope::mainFile)
            {
                sub->parent_ = nullptr;
                dict.header_ = std::move(sub);
            }
            return;
        }
        add(dict, entry(key, std::move(sub), tk.file(), keyTok.line,
                        isPattern), mode_);
        return;
    }

    const std::vector<token> raw = readValue(tk, key, keyTok.line);

    // key $dict; copies the sub-dictionary.
    if (raw.size() == 1 && raw[0].type == token::kind::variable)
    {
        const resolved r = resolve(dict, raw[0].text, tk.file(), raw[0].line,
            " in the value of keyword '" + clip(key) + "'");
        if (r.ent && r.ent->isDict())
        {
            auto copy = std::make_unique<dictionary>(r.ent->dict());
            add(dict, entry(key, std::move(copy), tk.file(), keyTok.line,
                            isPattern), mode_);
            return;
        }
    }

    add(dict, entry(key, expandValue(dict, raw, key, tk.file()), tk.file(),
                    keyTok.line, isPattern), mode_);
}


std::vector<token> dictionaryParser::readValue(tokeniser& tk,
                                               const std::string& key,
                                               int keyLine)
{
    std::vector<token> raw;
    std::vector<token> open;   // unclosed ( and {
    int lastLine = keyLine;
    token t;
    while (true)
    {
        if (!tk.read(t))
        {
            if (!open.empty())
            {
                const token& o = open.back();
                fatalIOError(tk.file(), o.line, "Unexpected end of file in "
                    "the value of keyword '" + clip(key) + "': expected '"
                    + (o.isPunctuation('(') ? ")" : "}") + "' to close '"
                    + o.text + "' opened at line " + std::to_string(o.line),
                    key);
            }
            fatalIOError(tk.file(), keyLine, "Unexpected end of file after "
                "the value of keyword '" + clip(key) + "' (line "
                + std::to_string(keyLine) + "): expected ';'", key);
        }

        if (t.type == token::kind::punctuation)
        {
            if (open.empty() && t.isPunctuation(';'))
            {
                return raw;
            }
            if (t.isPunctuation('(') || t.isPunctuation('{'))
            {
                open.push_back(t);
            }
            else if (t.isPunctuation(')') || t.isPunctuation('}'))
            {
                if (open.empty())
                {
                    if (t.isPunctuation('}'))
                    {
                        fatalIOError(tk.file(), lastLine, "Missing ';' "
                            "after the value of keyword '" + clip(key)
                            + "': expected ';', found '}' at line "
                            + std::to_string(t.line), key);
                    }
                    fatalIOError(tk.file(), t.line, "Unmatched ')' in the "
                        "value of keyword '" + clip(key) + "': expected ';'",
                        key);
                }
                const bool paren = open.back().isPunctuation('(');
                const std::string closer = paren ? ")" : "}";
                if (t.text != closer)
                {
                    fatalIOError(tk.file(), t.line, "Mismatched '" + t.text
                        + "' in the value of keyword '" + key
                        + "': expected '" + closer + "' to close '"
                        + open.back().text + "' opened at line "
                        + std::to_string(open.back().line), key);
                }
                open.pop_back();
            }
        }
        raw.push_back(t);
        lastLine = t.line;
    }
}


std::vector<token> dictionaryParser::expandValue
(
    const dictionary& dict,
    const std::vector<token>& raw,
    const std::string& key,
    const std::string& file
)
{
    std::vector<token> out;
    out.reserve(raw.size());
    int depth = 0;   // of ( and { in raw: the expanded tokens balance
    for (const token& t : raw)
    {
        if (t.isPunctuation('(') || t.isPunctuation('{'))
        {
            ++depth;
        }
        else if (t.isPunctuation(')') || t.isPunctuation('}'))
        {
            --depth;
        }

        if (t.type == token::kind::variable)
        {
            const resolved r = resolve(dict, t.text, file, t.line,
                " in the value of keyword '" + clip(key) + "'");
            if (r.ent && r.ent->isDict())
            {
                if (depth == 0 && r.ent->dict().size())
                {
                    // Its entries' ';' would end this entry early.
                    fatalIOError(file, t.line, "The sub-dictionary $"
                        + clip(t.text) + " is expanded outside brackets in "
                        "the value of keyword '" + clip(key) + "': write '"
                        + clip(key) + " $" + clip(t.text) + ";' to copy it, "
                        "or expand it inside { } or ( )", key);
                }
                dictionaryDetail::appendDictTokens(r.ent->dict(), out,
                                                   t.line);
            }
            else
            {
                for (token x : (r.ent ? r.ent->tokens() : r.tokens))
                {
                    x.line = t.line;
                    out.push_back(std::move(x));
                }
            }
            if (out.size() > maxValueTokens)
            {
                fatalIOError(file, t.line, "The value of keyword '" + key
                    + "' grows past " + std::to_string(maxValueTokens)
                    + " tokens through $" + clip(t.text), key);
            }
        }
        else if (t.type == token::kind::directive)
        {
            if (!isKnownDirective(t.text))
            {
                refuseDirective(t.text, file, t.line);
            }
            fatalIOError(file, t.line, "Directive #" + clip(t.text)
                + " cannot appear inside the value of keyword '" + clip(key)
                + "': write it on its own, between entries", key);
        }
        else
        {
            out.push_back(t);
        }
    }
    return out;
}


void dictionaryParser::readDirective(dictionary& dict, tokeniser& tk,
                                     const token& t)
{
    const std::string& name = t.text;
    const std::string& file = tk.file();
    token a;

    if (isIncludeDirective(name))
    {
        const bool have = tk.read(a);
        if (!have || a.type != token::kind::string)
        {
            fatalIOError(file, have ? a.line : t.line, "Expected a quoted "
                "file name after #" + clip(name) + ", found "
                + foundText(have, a),
                "#" + name);
        }
        include(dict, tk, t, a.text,
            name == "includeIfPresent" || name == "sinclude",
            name == "includeEtc");
        return;
    }

    if (name == "remove")
    {
        std::vector<token> keys;
        bool have = tk.read(a);
        if (have && a.isPunctuation('('))
        {
            while ((have = tk.read(a)) && !a.isPunctuation(')'))
            {
                if (a.type != token::kind::word
                 && a.type != token::kind::string)
                {
                    fatalIOError(file, a.line, "Expected a keyword in the "
                        "list of #remove, found "
                        + dictionaryDetail::describe(a), "#remove");
                }
                keys.push_back(a);
            }
            if (!have)
            {
                fatalIOError(file, t.line, "Unexpected end of file in the "
                    "list of #remove: expected ')'", "#remove");
            }
        }
        else if (have
              && (a.type == token::kind::word
               || a.type == token::kind::string))
        {
            keys.push_back(a);
        }
        else
        {
            fatalIOError(file, have ? a.line : t.line, "Expected a keyword "
                "or a list (a b ...) after #remove, found "
                + foundText(have, a), "#remove");
        }

        auto& entries = dict.entries_;
        for (const token& k : keys)
        {
            const bool regex = k.type == token::kind::string;
            entries.erase
            (
                std::remove_if
                (
                    entries.begin(), entries.end(),
                    [&](const entry& e)
                    {
                        if (e.keyword() == k.text)
                        {
                            return true;
                        }
                        try
                        {
                            return regex
                                && dictionaryDetail::regexMatch(k.text,
                                                                e.keyword());
                        }
                        catch (const std::regex_error& err)
                        {
                            fatalIOError(file, k.line, "Invalid regular "
                                "expression \"" + clip(k.text)
                                + "\" in #remove: "
                                + err.what(), "#remove");
                        }
                    }
                ),
                entries.end()
            );
        }
        return;
    }

    if (name == "inputMode")
    {
        const bool have = tk.read(a);
        const std::vector<std::string> modes =
            {"merge", "overwrite", "protect", "warn", "error", "default"};
        if (!have || a.type != token::kind::word
         || std::find(modes.begin(), modes.end(), a.text) == modes.end())
        {
            fatalIOError(file, have ? a.line : t.line, "Expected one of "
                + str(modes) + " after #inputMode, "
                "found " + foundText(have, a), "#inputMode");
        }
        if (a.text == "merge" || a.text == "default")
        {
            mode_ = inputMode::merge;
        }
        else if (a.text == "overwrite")
        {
            mode_ = inputMode::overwrite;
        }
        else if (a.text == "protect")
        {
            mode_ = inputMode::protect;
        }
        else if (a.text == "warn")
        {
            mode_ = inputMode::warn;
        }
        else
        {
            mode_ = inputMode::error;
        }
        return;
    }

    refuseDirective(name, file, t.line);
}


void dictionaryParser::readKeyVariable(dictionary& dict, tokeniser& tk,
                                       const token& t, scope where)
{
    token next;
    const bool haveNext = tk.peek(next);
    const resolved r = resolve(dict, t.text, tk.file(), t.line,
                               " in keyword position", true);

    if (haveNext && next.isPunctuation('{'))
    {
        // $name { ... }: the value of name is the keyword.
        if (r.ent && r.ent->isDict())
        {
            fatalIOError(tk.file(), t.line, "'$" + clip(t.text) + "' used "
                "as a keyword must name a single word, but it is a "
                "sub-dictionary", "$" + t.text);
        }
        const std::vector<token>& v = r.ent ? r.ent->tokens() : r.tokens;
        if (v.size() != 1
         || (v[0].type != token::kind::word
          && v[0].type != token::kind::string))
        {
            fatalIOError(tk.file(), t.line, "'$" + clip(t.text) + "' used "
                "as a keyword must name a single word, found '"
                + clip(dictionaryDetail::joinTokens(v)) + "'", "$" + t.text);
        }
        token key = v[0];
        key.line = t.line;
        readEntry(dict, tk, key, where);
        return;
    }

    // $name; splices the entries of sub-dictionary name.
    if (!r.ent || !r.ent->isDict())
    {
        fatalIOError(tk.file(), t.line, "Cannot splice '$" + clip(t.text)
            + "' into dictionary \"" + dict.name() + "\": it is not a "
            "sub-dictionary (a $name in keyword position copies the entries "
            "of a sub-dictionary)", "$" + t.text);
    }
    dictionary source(r.ent->dict());
    for (auto& e : source.entries_)
    {
        add(dict, std::move(e), mode_);
    }
}


void dictionaryParser::include(dictionary& dict, tokeniser& tk,
                               const token& directive,
                               const std::string& name, bool optional,
                               bool etc)
{
    namespace fs = std::filesystem;
    const std::string& file = tk.file();
    const std::string what = "#" + directive.text;
    const fs::path given
    (
        expandText(dict, name, file, directive.line,
                   " in the file name of " + what)
    );

    std::vector<fs::path> candidates;
    if (given.is_absolute())
    {
        candidates.push_back(given);
    }
    else if (etc)
    {
        if (const char* home = std::getenv("HOME"))
        {
            candidates.push_back(fs::path(home)/".sphvcpm"/"etc"/given);
        }
        if (const char* dir = std::getenv("SPHVCPM_DIR"))
        {
            candidates.push_back(fs::path(dir)/"etc"/given);
        }
        else if (!optional)
        {
            fatalIOError(file, directive.line, what + " \"" + clip(name)
                + "\": SPHVCPM_DIR is not set (source etc/bashrc of the "
                "installation)", what);
        }
    }
    else
    {
        candidates.push_back(fs::path(file).parent_path()/given);
    }

    std::error_code ec;
    const fs::path* found = nullptr;
    for (const auto& c : candidates)
    {
        if (fs::is_regular_file(c, ec))
        {
            found = &c;
            break;
        }
    }
    if (!found)
    {
        if (optional)
        {
            return;   // also a directory or device, as OpenFOAM
        }
        // There, but not a file (a directory, /dev/null): not "missing".
        for (const auto& c : candidates)
        {
            checkRegularFile(c, file, directive.line, what + " file");
        }
        std::vector<std::string> looked;
        for (const auto& c : candidates)
        {
            looked.push_back("\"" + clip(c.string(), maxPathShown) + "\"");
        }
        fatalIOError(file, directive.line, "Cannot find " + what + " file \""
            + clip(name) + "\": looked for " + str(looked),
            what);
    }

    const std::string canonical = fs::weakly_canonical(*found, ec).string();
    if
    (
        std::find(includeStack_.begin(), includeStack_.end(), canonical)
     != includeStack_.end()
    )
    {
        std::string chain;
        for (const auto& f : includeStack_)
        {
            chain += f + " -> ";
        }
        fatalIOError(file, directive.line, "Recursive " + what + " of \""
            + clip(name) + "\": include chain " + chain + canonical, what);
    }
    if (includeStack_.size() >= maxIncludeDepth)
    {
        fatalIOError(file, directive.line, what + " of \"" + clip(name)
            + "\" nested more than " + std::to_string(maxIncludeDepth)
            + " levels deep", what);
    }

    const std::string text =
        readWholeFile(*found, file, directive.line, what + " file");
    includeStack_.push_back(canonical);
    parseText(dict, text, found->string(), scope::includedFile);
    includeStack_.pop_back();
}


dictionaryParser::resolved dictionaryParser::resolve
(
    const dictionary& dict,
    const std::string& var,
    const std::string& file,
    int line,
    const std::string& context,
    bool patterns
) const
{
    std::string name = var;
    if (name.size() >= 2 && name.front() == '{' && name.back() == '}')
    {
        name = expandText(dict, name.substr(1, name.size() - 2), file, line,
                          context);
    }

    resolved r;
    const dictionary* searched = &dict;
    std::vector<const entry*> through;
    r.ent = findScoped(dict, name, patterns, &searched, &through);
    if (r.ent)
    {
        // A variable of the case, not a misspelt keyword (checkKeywords),
        // and so is a sub-dictionary of parameters it is read from
        // ($sub/x). The entries belong to the dictionary being read.
        const_cast<entry*>(r.ent)->markUsedAsVariable();
        for (const entry* e : through)
        {
            const_cast<entry*>(e)->markUsedAsVariable();
        }
        return r;
    }

    if (const char* env = std::getenv(name.c_str()))
    {
        // Words and numbers stay tokens; anything the lexer would split
        // oddly (a path) becomes one string.
        const std::string value(env);
        try
        {
            r.tokens = tokeniser::tokenise(value, "$" + name);
            for (const token& t : r.tokens)
            {
                if (t.isPunctuation('/'))
                {
                    throw FatalError("path");
                }
            }
        }
        catch (const FatalError&)
        {
            r.tokens = {dictionaryDetail::stringToken(value)};
        }
        return r;
    }

    const std::vector<std::string> keys = searched->keys();
    // Suggest for the last component of a scoped name.
    const auto cut = name.find_last_of("/!:");
    const std::string base =
        cut == std::string::npos ? name : name.substr(cut + 1);
    const std::string guess = dictionaryDetail::closest(base, keys);
    fatalIOError(file, line, "Undefined variable '$" + clip(var) + "'"
        + context + ": no keyword '" + clip(name) + "' in dictionary \""
        + searched->name()
        + "\" or its parents, and no environment variable of that name."
        + (guess.empty() ? "" : " Did you mean '" + clip(guess) + "'?")
        + " Valid keywords are: " + str(clip(keys)),
        "$" + var);
}


std::string dictionaryParser::expandText
(
    const dictionary& dict,
    const std::string& text,
    const std::string& file,
    int line,
    const std::string& context
) const
{
    std::string out;
    std::size_t i = 0;
    if (text.size() >= 1 && text[0] == '~'
     && (text.size() == 1 || text[1] == '/'))
    {
        if (const char* home = std::getenv("HOME"))
        {
            out = home;
            i = 1;
        }
    }

    // ESI's <case>, <system> and <constant> tags: $FOAM_CASE when set,
    // else the case holding the file being read (case/system/controlDict).
    for (const char* tag : {"<case>", "<system>", "<constant>"})
    {
        const std::string t(tag);
        if (text.compare(0, t.size(), t) == 0)
        {
            namespace fs = std::filesystem;
            const char* env = std::getenv("FOAM_CASE");
            fs::path caseDir = env ? fs::path(env)
                : includeStack_.empty() ? fs::path(".")
                : fs::path(includeStack_.front()).parent_path().parent_path();
            if (t != "<case>")
            {
                caseDir /= t.substr(1, t.size() - 2);
            }
            out = caseDir.string();
            i = t.size();
            break;
        }
    }

    while (i < text.size())
    {
        if (text[i] != '$')
        {
            out += text[i++];
            continue;
        }
        std::string name;
        std::size_t j = i + 1;
        if (j < text.size() && text[j] == '{')
        {
            int depth = 0;
            std::size_t k = j;
            for (; k < text.size(); ++k)
            {
                if (text[k] == '{')
                {
                    ++depth;
                }
                else if (text[k] == '}' && --depth == 0)
                {
                    break;
                }
            }
            if (k >= text.size())
            {
                fatalIOError(file, line, "Unterminated '${' in \""
                    + clip(text)
                    + "\"" + context + ": expected '}'");
            }
            if (++textDepth_ > maxNameDepth)
            {
                fatalIOError(file, line, "Variable names nested more than "
                    + std::to_string(maxNameDepth) + " levels deep in \""
                    + clip(text) + "\"" + context);
            }
            name = expandText(dict, text.substr(j + 1, k - j - 1), file,
                              line, context);
            --textDepth_;
            i = k + 1;
        }
        else
        {
            while (j < text.size()
                && (std::isalnum(static_cast<unsigned char>(text[j]))
                 || text[j] == '_'))
            {
                name += text[j++];
            }
            if (name.empty())
            {
                out += text[i++];   // a lone $ stays
                continue;
            }
            i = j;
        }

        const resolved r = resolve(dict, name, file, line, context);
        if (r.ent && r.ent->isDict())
        {
            fatalIOError(file, line, "Variable '$" + clip(name) + "'" + context
                + " names a sub-dictionary; expected a word or string");
        }
        const std::vector<token>& v = r.ent ? r.ent->tokens() : r.tokens;
        if (v.size() == 1
         && (v[0].type == token::kind::word
          || v[0].type == token::kind::string))
        {
            out += v[0].text;
        }
        else
        {
            out += dictionaryDetail::joinTokens(v);
        }
    }
    return out;
}

} // End namespace sphvcpm
