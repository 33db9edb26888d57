/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// Entries, lookup, editing and writing of dictionaries. Reading is in
// dictionaryParser.C and typed values in dictionaryValues.C.

#include "dictionary.H"
#include "dictionaryParser.H"
#include "error.H"
#include "foamFile.H"
#include "tokeniser.H"
#include "formatting.H"

#include <algorithm>
#include <cctype>
#include <map>
#include <utility>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <regex>
#include <sstream>
#include <unordered_map>

namespace sphvcpm
{

// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

std::size_t dictionaryDetail::editDistance(const std::string& a,
                                           const std::string& b)
{
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
    {
        prev[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t subst = prev[j - 1] + (a[i - 1] != b[j - 1]);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}


std::string dictionaryDetail::closest(const std::string& key,
                                      const std::vector<std::string>& cands)
{
    std::string best;
    std::size_t bestDistance = std::string::npos;
    for (const auto& c : cands)
    {
        const std::size_t d = editDistance(key, c);
        if (d < bestDistance)
        {
            best = c;
            bestDistance = d;
        }
    }
    // A misspelling changes a few characters, not most of the word.
    const std::size_t limit = std::max<std::size_t>(2, key.size()/3);
    if (best.empty() || bestDistance > limit || bestDistance >= key.size())
    {
        return "";
    }
    return best;
}


std::string dictionaryDetail::synonymOf(const std::string& key,
    const std::vector<std::string>& candidates)
{
    // Lower case, without '_' and '-': youngs_modulus, Young-Modulus.
    std::string k;
    for (const char c : key)
    {
        if (c != '_' && c != '-') k += char(std::tolower((unsigned char)c));
    }
    static const std::vector<std::pair<std::string, std::vector<std::string>>>
    names
    {
        {"E", {"emod", "emodulus", "young", "youngs", "youngmodulus",
               "youngsmodulus", "elasticmodulus", "elasticitymodulus",
               "modulus", "ym"}},
        {"nu", {"poisson", "poissons", "poissonratio", "poissonsratio",
                "poissoncoefficient", "pr"}},
        {"rho", {"density", "dens", "massdensity"}},
        {"rho0", {"density", "rhop0", "referencedensity"}},
    };
    for (const auto& [keyword, others] : names)
    {
        if (std::find(candidates.begin(), candidates.end(), keyword)
                != candidates.end()
         && std::find(others.begin(), others.end(), k) != others.end())
        {
            return keyword;
        }
    }
    return "";
}


std::string dictionaryDetail::clip(const std::string& text,
                                   const std::size_t shown)
{
    if (text.size() <= shown)
    {
        return text;
    }
    // UTF-8: not cut inside a character, and characters counted (not
    // their continuation bytes).
    const auto continuation = [](char c)
    {
        return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
    };
    std::size_t cut = shown;
    while (cut > 0 && continuation(text[cut]))
    {
        --cut;
    }
    const std::size_t characters = std::size_t(std::count_if
    (
        text.begin(), text.end(), [&](char c){ return !continuation(c); }
    ));
    if (characters <= shown)
    {
        return text;
    }
    return text.substr(0, cut) + "... (" + std::to_string(characters)
        + " characters)";
}


std::vector<std::string> dictionaryDetail::clip
(
    const std::vector<std::string>& words
)
{
    std::vector<std::string> out;
    out.reserve(words.size());
    for (const auto& w : words)
    {
        out.push_back(clip(w));
    }
    return out;
}


std::string dictionaryDetail::describe(const token& t)
{
    switch (t.type)
    {
        case token::kind::punctuation: return "'" + t.text + "'";
        case token::kind::word: return "word '" + clip(t.text) + "'";
        case token::kind::string: return "string " + quote(clip(t.text));
        case token::kind::integer: return "integer " + clip(t.str());
        case token::kind::floating:
            return "floating-point number " + clip(t.str());
        case token::kind::variable: return "variable '$" + clip(t.text) + "'";
        case token::kind::directive:
            return "directive '#" + clip(t.text) + "'";
        case token::kind::verbatim: return "verbatim string #{...#}";
    }
    return "'" + clip(t.text) + "'";
}


std::string dictionaryDetail::formatScalar(double v)
{
    for (int precision = 1; precision <= 17; ++precision)
    {
        std::ostringstream os;
        os << std::setprecision(precision) << v;
        if (std::strtod(os.str().c_str(), nullptr) == v)
        {
            return os.str();
        }
    }
    std::ostringstream os;
    os << std::setprecision(17) << v;
    return os.str();
}


token dictionaryDetail::numberToken(double v)
{
    token t;
    t.text = formatScalar(v);
    t.floatValue = v;
    t.type = token::kind::floating;
    const bool integral = t.text.find_first_not_of("-0123456789")
        == std::string::npos;
    if (integral)
    {
        errno = 0;
        const long long i = std::strtoll(t.text.c_str(), nullptr, 10);
        if (errno != ERANGE)
        {
            t.type = token::kind::integer;
            t.integerValue = i;
        }
    }
    return t;
}


token dictionaryDetail::integerToken(std::int64_t v)
{
    token t;
    t.type = token::kind::integer;
    t.integerValue = v;
    t.floatValue = double(v);
    t.text = std::to_string(v);
    return t;
}


token dictionaryDetail::wordToken(const std::string& text)
{
    token t;
    t.type = token::kind::word;
    t.text = text;
    return t;
}


token dictionaryDetail::stringToken(const std::string& text)
{
    token t;
    t.type = token::kind::string;
    t.text = text;
    return t;
}


token dictionaryDetail::punctuationToken(char c)
{
    token t;
    t.type = token::kind::punctuation;
    t.text = std::string(1, c);
    return t;
}


std::string dictionaryDetail::quote(const std::string& text)
{
    // The reader keeps backslashes, except one that escapes a quote or a
    // newline; so a run of backslashes before either must be even before
    // the escaping one is added. (An odd run there cannot be written
    // exactly in OpenFOAM's format: it gains one backslash.) The reader
    // takes "\r\n" and a lone '\r' for line ends: written as '\n', so that
    // they read back (as '\n').
    std::string out = "\"";
    std::size_t run = 0;
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        char c = text[i];
        if (c == '\r')
        {
            if (i + 1 < text.size() && text[i + 1] == '\n')
            {
                continue;
            }
            c = '\n';
        }
        if (c == '"' || c == '\n')
        {
            out += (run % 2 == 0) ? "\\" : "\\\\";
        }
        out += c;
        run = (c == '\\') ? run + 1 : 0;
    }
    if (run % 2 == 1)
    {
        out += '\\';
    }
    return out + "\"";
}


std::string dictionaryDetail::joinTokens(const std::vector<token>& tokens)
{
    // Written the way OpenFOAM writes them: (1 2 3), 3(1 2 3), 10{0},
    // [0 2 -1 0 0 0 0], [kg/m^3], and re-read as the same tokens.
    std::string out;
    std::vector<bool> braces;   // open '{': true for N{v} (written tight)
    int units = 0;              // depth of '[' (dimensions)
    for (std::size_t i = 0; i < tokens.size(); ++i)
    {
        const token& b = tokens[i];
        bool tight = false;
        if (i > 0)
        {
            const token& a = tokens[i - 1];
            const bool aSlash = a.isPunctuation('/');
            const bool bSlash = b.isPunctuation('/');
            tight =
                a.isPunctuation('(') || a.isPunctuation('[')
             || b.isPunctuation(')')
             // the lexer would glue ']' onto a word or a variable
             || (b.isPunctuation(']') && a.type != token::kind::word
              && a.type != token::kind::variable)
             || (a.type == token::kind::integer
              && (b.isPunctuation('(') || b.isPunctuation('{')))
             || (a.isPunctuation('{') && !braces.empty() && braces.back())
             || (b.isPunctuation('}') && !braces.empty() && braces.back())
             // m^2/s inside units, but never // or /* (comments)
             || (units > 0 && (aSlash || bSlash)
              && !(aSlash && (bSlash || b.isPunctuation('*')))
              && !(bSlash && a.isPunctuation('*')));
            if (!tight)
            {
                out += ' ';
            }
        }
        if (b.isPunctuation('{'))
        {
            braces.push_back
            (
                i > 0 && tokens[i - 1].type == token::kind::integer
            );
        }
        else if (b.isPunctuation('}') && !braces.empty())
        {
            braces.pop_back();
        }
        else if (b.isPunctuation('['))
        {
            ++units;
        }
        else if
        (
            units > 0
         && (b.isPunctuation(']')
          || (b.type == token::kind::word && !b.text.empty()
           && b.text.back() == ']'))
        )
        {
            --units;
        }
        out += b.str();
    }
    return out;
}


bool dictionaryDetail::regexMatch(const std::string& pattern,
                                  const std::string& key)
{
    thread_local std::unordered_map<std::string, std::regex> cache;
    auto iter = cache.find(pattern);
    if (iter == cache.end())
    {
        iter = cache.emplace(pattern, std::regex(pattern)).first;
    }
    return std::regex_match(key, iter->second);
}


void dictionaryDetail::checkRegex(const std::string& pattern)
{
    regexMatch(pattern, "");
}


void dictionaryDetail::appendDictTokens(const dictionary& d,
                                        std::vector<token>& out, int line)
{
    auto push = [&](token t)
    {
        t.line = line;
        out.push_back(std::move(t));
    };
    for (const auto& key : d.keys())
    {
        const entry& e = *d.findEntry(key);
        push(e.isPattern() ? stringToken(key) : wordToken(key));
        if (e.isDict())
        {
            push(punctuationToken('{'));
            appendDictTokens(e.dict(), out, line);
            push(punctuationToken('}'));
        }
        else
        {
            for (const auto& t : e.tokens())
            {
                push(t);
            }
            push(punctuationToken(';'));
        }
    }
}


// * * * * * * * * * * * * * * * * * token * * * * * * * * * * * * * * * * //

std::string token::str() const
{
    switch (type)
    {
        case kind::string:
            return dictionaryDetail::quote(text);
        case kind::integer:
            return text.empty() ? std::to_string(integerValue) : text;
        case kind::floating:
            return text.empty()
                 ? dictionaryDetail::formatScalar(floatValue) : text;
        case kind::variable:
            return "$" + text;
        case kind::directive:
            return "#" + text;
        case kind::verbatim:
            return "#{" + text + "#}";
        default:
            return text;
    }
}


// * * * * * * * * * * * * * * * * * entry * * * * * * * * * * * * * * * * //

entry::entry(std::string keyword, std::vector<token> tokens,
             std::string file, int line, bool isPattern)
:
    keyword_(std::move(keyword)),
    tokens_(std::move(tokens)),
    file_(std::move(file)),
    line_(line),
    isPattern_(isPattern)
{}


entry::entry(std::string keyword, std::unique_ptr<dictionary> dict,
             std::string file, int line, bool isPattern)
:
    keyword_(std::move(keyword)),
    dict_(dict ? std::move(dict) : std::make_unique<dictionary>(keyword_)),
    file_(std::move(file)),
    line_(line),
    isPattern_(isPattern)
{}


entry::entry(const entry& e)
:
    keyword_(e.keyword_),
    tokens_(e.tokens_),
    dict_(e.dict_ ? std::make_unique<dictionary>(*e.dict_) : nullptr),
    file_(e.file_),
    line_(e.line_),
    isPattern_(e.isPattern_),
    usedAsVariable_(e.usedAsVariable_),
    mergedFile_(e.mergedFile_),
    mergedLine_(e.mergedLine_)
{}


entry::entry(entry&&) noexcept = default;
entry& entry::operator=(entry&&) noexcept = default;
entry::~entry() = default;


entry& entry::operator=(const entry& e)
{
    if (this != &e)
    {
        entry copy(e);
        *this = std::move(copy);
    }
    return *this;
}


const dictionary& entry::dict() const
{
    if (!dict_)
    {
        fatalIOError(file_, line_, "Keyword '"
            + dictionaryDetail::clip(keyword_) + "' is not a sub-dictionary:"
            " expected '{', found the value '"
            + dictionaryDetail::clip(dictionaryDetail::joinTokens(tokens_))
            + "'", keyword_);
    }
    return *dict_;
}


dictionary& entry::dict()
{
    return const_cast<dictionary&>(static_cast<const entry&>(*this).dict());
}


const std::vector<token>& entry::tokens() const
{
    if (dict_)
    {
        fatalIOError(file_, line_, "Keyword '"
            + dictionaryDetail::clip(keyword_) + "' is a sub-dictionary "
            "(opened at line " + std::to_string(dict_->line())
            + "), not a value", keyword_);
    }
    return tokens_;
}


// * * * * * * * * * * * * * * * * dictionary * * * * * * * * * * * * * * //

dictionary::dictionary(std::string name)
:
    name_(name),
    file_(std::move(name))
{}


dictionary::dictionary(const dictionary& d)
:
    name_(d.name_),
    file_(d.file_),
    line_(d.line_),
    parent_(nullptr),
    entries_(d.entries_),
    header_(d.header_ ? std::make_unique<dictionary>(*d.header_) : nullptr),
    fewestVectorComponents_(d.topDict().fewestVectorComponents_)
{
    reparent();
}


dictionary& dictionary::operator=(const dictionary& d)
{
    if (this != &d)
    {
        // Through a copy: d may live inside this dictionary.
        dictionary copy(d);
        *this = std::move(copy);
    }
    return *this;
}


dictionary::dictionary(dictionary&& d) noexcept
:
    name_(std::move(d.name_)),
    file_(std::move(d.file_)),
    line_(d.line_),
    parent_(d.parent_),
    entries_(std::move(d.entries_)),
    header_(std::move(d.header_)),
    fewestVectorComponents_(d.topDict().fewestVectorComponents_)
{
    d.parent_ = nullptr;
    reparent();
}


dictionary& dictionary::operator=(dictionary&& d) noexcept
{
    if (this != &d)
    {
        // Take everything out of d first: d may live inside this one.
        std::string name = std::move(d.name_);
        std::string file = std::move(d.file_);
        const int line = d.line_;
        std::vector<entry> entries = std::move(d.entries_);
        std::unique_ptr<dictionary> header = std::move(d.header_);
        const int fewest = d.topDict().fewestVectorComponents_;

        // A sub-dictionary keeps its place (parent and scoped name); a
        // top-level one takes the name of what it is given.
        if (!parent_)
        {
            name_ = std::move(name);
        }
        file_ = std::move(file);
        line_ = line;
        entries_ = std::move(entries);
        header_ = std::move(header);
        fewestVectorComponents_ = fewest;
        for (auto& e : entries_)
        {
            if (e.isDict())
            {
                dictionaryParser::adopt(e.dict(), *this, e.keyword());
            }
        }
    }
    return *this;
}


dictionary::~dictionary() = default;


void dictionary::reparent()
{
    for (auto& e : entries_)
    {
        if (e.isDict())
        {
            e.dict().parent_ = this;
        }
    }
}


dictionary dictionary::fromFile(const std::filesystem::path& file)
{
    return dictionaryParser::readFile(file);
}


void dictionary::setCaseDimensions(const int nDimensions)
{
    fewestVectorComponents_ = nDimensions == 3 ? 3 : 2;
}


dictionary dictionary::fromString(const std::string& text,
                                  const std::string& name)
{
    return dictionaryParser::readString(text, name);
}


const dictionary& dictionary::topDict() const
{
    const dictionary* d = this;
    while (d->parent_)
    {
        d = d->parent_;
    }
    return *d;
}


const dictionary* dictionary::header() const
{
    return header_.get();
}


bool dictionary::found(const std::string& key) const
{
    return findEntry(key) != nullptr;
}


bool dictionary::isDict(const std::string& key) const
{
    const entry* e = findEntry(key);
    return e && e->isDict();
}


const entry* dictionary::findEntry(const std::string& key) const
{
    for (const auto& e : entries_)
    {
        if (e.keyword() == key)
        {
            return &e;
        }
    }
    // Patterns last first: a later, more specific pattern wins.
    for (auto iter = entries_.rbegin(); iter != entries_.rend(); ++iter)
    {
        try
        {
            if (iter->isPattern()
             && dictionaryDetail::regexMatch(iter->keyword(), key))
            {
                return &*iter;
            }
        }
        catch (const std::regex_error& err)
        {
            // Only an entry made in code can get here: the reader checks.
            fatalIOError(iter->file(), iter->line(), "Invalid regular "
                "expression \"" + dictionaryDetail::clip(iter->keyword())
                + "\" as keyword: "
                + err.what(), iter->keyword());
        }
    }
    return nullptr;
}


const entry& dictionary::lookupEntry(const std::string& key) const
{
    if (const entry* e = findEntry(key))
    {
        return *e;
    }
    const std::vector<std::string> present = keys();
    const std::string guess = dictionaryDetail::closest(key, present);
    // Emod given for E: what other codes call it.
    std::string other;
    for (const std::string& k : present)
    {
        if (guess.empty() && other.empty()
         && dictionaryDetail::synonymOf(k, {key}) == key)
        {
            other = k;
        }
    }
    fatalIOError(file_, line_, "Keyword '" + dictionaryDetail::clip(key)
        + "' is undefined in dictionary \"" + name_ + "\"."
        + (!guess.empty()
         ? " Did you mean '" + dictionaryDetail::clip(guess) + "'?"
         : !other.empty() ? " '" + dictionaryDetail::clip(other) + "' is"
           " not read here: write it as '" + key + "'." : "")
        + " Keywords present: " + str(dictionaryDetail::clip(present)),
        key);
}


const dictionary* dictionary::findDict(const std::string& key) const
{
    const entry* e = findEntry(key);
    return e && e->isDict() ? &e->dict() : nullptr;
}


const dictionary& dictionary::subDict(const std::string& key) const
{
    return lookupEntry(key).dict();
}


dictionary& dictionary::subDict(const std::string& key)
{
    return const_cast<dictionary&>
    (
        static_cast<const dictionary&>(*this).subDict(key)
    );
}


std::vector<std::string> dictionary::keys() const
{
    std::vector<std::string> k;
    k.reserve(entries_.size());
    for (const auto& e : entries_)
    {
        k.push_back(e.keyword());
    }
    return k;
}


std::vector<std::string> dictionary::subDictKeys() const
{
    std::vector<std::string> k;
    for (const auto& e : entries_)
    {
        if (e.isDict())
        {
            k.push_back(e.keyword());
        }
    }
    return k;
}


std::size_t dictionary::size() const
{
    return entries_.size();
}


void dictionary::checkKeywords(const std::vector<std::string>& valid) const
{
    // Entries of #include'd files this dictionary does not read, by file.
    std::map<std::string, std::vector<std::string>> unread;
    for (const auto& e : entries_)
    {
        if
        (
            e.isPattern() || e.usedAsVariable()
         || std::find(valid.begin(), valid.end(), e.keyword()) != valid.end()
        )
        {
            continue;
        }
        const std::string guess =
            dictionaryDetail::closest(e.keyword(), valid);
        // A parameter of an #include'd file that several dictionaries
        // share need not be used in each, unless it reads as a misspelling
        // of a keyword of this one: a warning names them.
        if (guess.empty() && !e.file().empty() && e.file() != file_)
        {
            unread[e.file()].push_back(e.keyword());
            continue;
        }
        const std::string suggestion = guess.empty()
            ? dictionaryDetail::synonymOf(e.keyword(), valid) : guess;
        fatalIOError(e.file(), e.line(), "Unknown keyword '"
            + dictionaryDetail::clip(e.keyword()) + "' in dictionary \""
            + name_ + "\"."
            + (suggestion.empty() ? "" : " Did you mean '" + suggestion
               + "'?")
            + " Valid keywords are: " + str(valid),
            e.keyword());
    }
    for (const auto& [file, keywords] : unread)
    {
        warning("Dictionary \"" + name_ + "\" does not read "
            + str(dictionaryDetail::clip(keywords))
            + " of the file it #includes: parameters for other dictionaries"
            " are fine there, a keyword meant for this one is not read."
            " Valid keywords are: " + str(valid), file);
    }
}


namespace
{

// A keyword made in code must read back as the same keyword.
void checkKeyword(const dictionary& d, const std::string& key)
{
    if (!isValidWord(key))
    {
        d.fatal("Invalid keyword '" + dictionaryDetail::clip(key)
            + "' for dictionary \"" + d.name()
            + "\": a keyword is one word (no spaces, quotes, / ; { } $, and "
            "not starting with a digit, '.', '-' or punctuation)", key);
    }
}

} // End anonymous namespace


void dictionary::setTokens(const std::string& key, std::vector<token> tokens)
{
    checkKeyword(*this, key);
    entry e(key, std::move(tokens), file_, 0);
    for (auto& x : entries_)
    {
        if (x.keyword() == key)
        {
            x = std::move(e);
            return;
        }
    }
    entries_.push_back(std::move(e));
}


dictionary& dictionary::setSubDict(const std::string& key)
{
    checkKeyword(*this, key);
    for (auto& x : entries_)
    {
        if (x.keyword() == key)
        {
            if (!x.isDict())
            {
                x = entry(key, std::make_unique<dictionary>(), file_, 0);
            }
            dictionaryParser::adopt(x.dict(), *this, key);
            x.dict().file_ = file_;
            return x.dict();
        }
    }
    entries_.emplace_back(key, std::make_unique<dictionary>(), file_, 0);
    dictionary& d = entries_.back().dict();
    dictionaryParser::adopt(d, *this, key);
    d.file_ = file_;
    return d;
}


bool dictionary::remove(const std::string& key)
{
    for (auto iter = entries_.begin(); iter != entries_.end(); ++iter)
    {
        if (iter->keyword() == key)
        {
            entries_.erase(iter);
            return true;
        }
    }
    return false;
}


void dictionary::write(std::ostream& os, int indentLevel) const
{
    const std::string indent(4*std::max(indentLevel, 0), ' ');
    bool first = true;
    for (const auto& e : entries_)
    {
        // OpenFOAM leaves a blank line between top-level entries.
        if (indentLevel == 0 && !first)
        {
            os << '\n';
        }
        first = false;

        const std::string key = e.isPattern()
            ? dictionaryDetail::quote(e.keyword()) : e.keyword();
        if (e.isDict())
        {
            os << indent << key << '\n' << indent << "{\n";
            e.dict().write(os, indentLevel + 1);
            os << indent << "}\n";
            continue;
        }
        os << indent << key;
        const auto& tokens = e.tokens();
        if (!tokens.empty())
        {
            // Values start at column 16 after the indent (keyType.C).
            const std::size_t pad = key.size() < 15 ? 16 - key.size() : 1;
            os << std::string(pad, ' ') << dictionaryDetail::joinTokens(tokens);
        }
        os << ";\n";
    }
}


void dictionary::writeFile(const std::filesystem::path& file,
                           const std::string& location) const
{
    std::ofstream os(file);
    if (!os)
    {
        fatalIOError(file.string(), 0, "Cannot open \"" + file.string()
            + "\" for writing");
    }
    foamFileHeader header;
    header.object = file.filename().string();
    header.location = location;
    writeFoamFileHeader(os, header);
    write(os);
    writeFoamFileEnd(os);
    os.close();
    if (!os)
    {
        fatalIOError(file.string(), 0, "Error writing \"" + file.string()
            + "\"");
    }
}


namespace
{

bool sameToken(const token& a, const token& b)
{
    if (a.isNumber() && b.isNumber())
    {
        if (a.type == token::kind::integer && b.type == token::kind::integer)
        {
            return a.integerValue == b.integerValue;
        }
        return a.floatValue == b.floatValue;
    }
    return a.type == b.type && a.text == b.text;
}

} // End anonymous namespace


bool dictionary::operator==(const dictionary& other) const
{
    if (entries_.size() != other.entries_.size())
    {
        return false;
    }
    for (std::size_t i = 0; i < entries_.size(); ++i)
    {
        const entry& a = entries_[i];
        const entry& b = other.entries_[i];
        if
        (
            a.keyword() != b.keyword() || a.isPattern() != b.isPattern()
         || a.isDict() != b.isDict()
        )
        {
            return false;
        }
        if (a.isDict())
        {
            if (a.dict() != b.dict())
            {
                return false;
            }
            continue;
        }
        const auto& ta = a.tokens();
        const auto& tb = b.tokens();
        if
        (
            ta.size() != tb.size()
         || !std::equal(ta.begin(), ta.end(), tb.begin(), sameToken)
        )
        {
            return false;
        }
    }
    return true;
}


void dictionary::fatal(const std::string& message,
                       const std::string& keyword) const
{
    fatalIOError(file_, line_, message, keyword);
}


void dictionary::fatalAt(const std::string& key,
                         const std::string& message) const
{
    if (const entry* e = findEntry(key))
    {
        fatalIOError(e->file(), e->line(), message, key);
    }
    fatal(message, key);
}

} // End namespace sphvcpm
