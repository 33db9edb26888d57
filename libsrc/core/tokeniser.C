/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The dictionary lexer (see tokeniser.H).

#include "tokeniser.H"
#include "dictionaryParser.H"
#include "error.H"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace sphvcpm
{

namespace
{

bool isSpace(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'
        || c == '\v';
}

bool isDigit(int c)
{
    return c >= '0' && c <= '9';
}

// One-character tokens; '/' is handled with the comments and '-' with the
// numbers.
bool isPunctuationChar(int c)
{
    return c != 0 && std::strchr(";()[]{}:,=+*", c) != nullptr;
}

bool isNumberChar(int c)
{
    return isDigit(c) || c == '+' || c == '-' || c == '.' || c == 'e'
        || c == 'E';
}

// What may follow the first character of a word (OpenFOAM's word::valid,
// plus '$' as in OpenFOAM-dev).
bool isWordChar(int c)
{
    return c >= 0 && !isSpace(c) && c != '"' && c != '\'' && c != '/'
        && c != ';' && c != '{' && c != '}' && c != '$';
}

bool isVariableChar(int c)
{
    return c >= 0 && !isSpace(c) && c != '"' && c != '\'' && c != ';'
        && c != '{' && c != '}' && c != '$';
}

// Old Mac files end lines with a lone '\r' and Windows ones with "\r\n":
// both become '\n', so that a // comment ends there (instead of taking the
// rest of the file), a string continues after a backslash and lines are
// counted once.
std::string unixLineEnds(std::string text)
{
    if (text.find('\r') == std::string::npos)
    {
        return text;
    }
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        if (text[i] != '\r')
        {
            out += text[i];
            continue;
        }
        out += '\n';
        if (i + 1 < text.size() && text[i + 1] == '\n')
        {
            ++i;
        }
    }
    return out;
}

// The UTF-8 byte-order mark some editors put first: not a keyword (it
// would be an invisible one).
std::string withoutByteOrderMark(std::string text)
{
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
    {
        text.erase(0, 3);
    }
    return text;
}

} // End anonymous namespace


tokeniser::tokeniser(std::string text, std::string file)
:
    text_(unixLineEnds(withoutByteOrderMark(std::move(text)))),
    file_(std::move(file))
{}


int tokeniser::get()
{
    if (pos_ >= text_.size())
    {
        return -1;
    }
    const int c = static_cast<unsigned char>(text_[pos_++]);
    if (c == '\n')
    {
        ++line_;
    }
    return c;
}


int tokeniser::look(std::size_t ahead) const
{
    return pos_ + ahead < text_.size()
         ? static_cast<unsigned char>(text_[pos_ + ahead]) : -1;
}


void tokeniser::error(int line, const std::string& message) const
{
    fatalIOError(file_, line, message);
}


bool tokeniser::skipSpace()
{
    while (true)
    {
        const int c = look();
        if (c < 0)
        {
            return false;
        }
        if (isSpace(c))
        {
            get();
        }
        else if (c == '/' && look(1) == '/')
        {
            while (look() >= 0 && look() != '\n')
            {
                get();
            }
        }
        else if (c == '/' && look(1) == '*')
        {
            const int start = line_;
            get();
            get();
            while (true)
            {
                const int d = get();
                if (d < 0)
                {
                    error(start, "Unterminated /* comment (opened at line "
                        + std::to_string(start)
                        + "): expected '*/', found end of file");
                }
                if (d == '*' && look() == '/')
                {
                    get();
                    break;
                }
            }
        }
        else
        {
            return true;
        }
    }
}


bool tokeniser::peek(token& t)
{
    if (!read(t))
    {
        return false;
    }
    pushedBack_.push_back(t);
    return true;
}


void tokeniser::putBack(const token& t)
{
    pushedBack_.push_back(t);
}


bool tokeniser::read(token& t)
{
    if (!pushedBack_.empty())
    {
        t = pushedBack_.back();
        pushedBack_.pop_back();
        return true;
    }
    if (!skipSpace())
    {
        return false;
    }

    t = token();
    t.line = line_;
    const int c = look();

    if (c == '"')
    {
        readString(t);
    }
    else if (c == '#')
    {
        readHash(t);
    }
    else if (c == '$')
    {
        readVariable(t);
    }
    else if (c == '/')
    {
        get();
        t.type = token::kind::punctuation;
        t.text = "/";
    }
    else if (isPunctuationChar(c))
    {
        get();
        t.type = token::kind::punctuation;
        t.text = std::string(1, char(c));
    }
    else if (isDigit(c) || c == '.' || c == '-')
    {
        readNumber(t);
    }
    else if (c == '\'')
    {
        error(line_, "Unexpected single quote: strings are written in "
            "double quotes (\"...\")");
    }
    else
    {
        readWord(t);
    }
    return true;
}


void tokeniser::readNumber(token& t)
{
    std::string buf;
    while (isNumberChar(look()))
    {
        buf += char(get());
    }
    if (buf == "-")
    {
        t.type = token::kind::punctuation;
        t.text = buf;
        return;
    }

    t.text = buf;
    const char* s = buf.c_str();
    const bool integral =
        buf.find_first_not_of("0123456789", buf[0] == '-' ? 1 : 0)
     == std::string::npos
     && buf.size() > (buf[0] == '-' ? 1u : 0u);

    if (integral)
    {
        errno = 0;
        char* end = nullptr;
        const long long v = std::strtoll(s, &end, 10);
        if (errno != ERANGE)
        {
            t.type = token::kind::integer;
            t.integerValue = v;
            t.floatValue = double(v);
            return;
        }
        // Too big even for 64 bits: kept as a floating-point number, and
        // an integer read of it reports the overflow.
    }

    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s, &end);
    if (end != s + buf.size())
    {
        error(t.line, "Bad number '" + dictionaryDetail::clip(buf) + "'");
    }
    if (errno == ERANGE && std::isinf(v))
    {
        // strtod gives infinity: no input means that.
        error(t.line, "Number '" + dictionaryDetail::clip(buf)
            + "' is too large (beyond the largest double, about 1.8e308)");
    }
    t.type = token::kind::floating;
    t.floatValue = v;
}


void tokeniser::readWord(token& t)
{
    t.type = token::kind::word;
    int depth = 0;
    int openLine = t.line;
    while (isWordChar(look()))
    {
        const int c = look();
        if (c == '(')
        {
            if (depth == 0)
            {
                openLine = line_;
            }
            ++depth;
        }
        else if (c == ')')
        {
            if (depth == 0)
            {
                break;   // an unmatched ')' ends the word: (a b)
            }
            --depth;
        }
        t.text += char(get());
    }
    if (depth > 0)
    {
        error(openLine, "Unbalanced parentheses in word '"
            + dictionaryDetail::clip(t.text)
            + "': expected ')', found "
            + (look() < 0 ? std::string("end of file")
                          : "'" + std::string(1, char(look())) + "'"));
    }
}


void tokeniser::readString(token& t)
{
    t.type = token::kind::string;
    const int start = line_;
    get();   // opening quote
    bool escaped = false;
    while (true)
    {
        const int c = get();
        if (c < 0)
        {
            error(start, "Unterminated string (opened at line "
                + std::to_string(start)
                + "): expected a closing '\"', found end of file");
        }
        if (c == '"')
        {
            if (!escaped)
            {
                return;
            }
            t.text.back() = '"';    // \" is a quote
            escaped = false;
        }
        else if (c == '\n')
        {
            if (!escaped)
            {
                error(line_ - 1, "Newline inside a string (opened at line "
                    + std::to_string(start) + "): expected a closing '\"'"
                    " (end a line with \\ to continue the string)");
            }
            t.text.back() = '\n';   // backslash-newline continues
            escaped = false;
        }
        else
        {
            // Other backslashes are kept, as OpenFOAM does (regular
            // expressions rely on it); a pair escapes itself.
            escaped = (c == '\\') ? !escaped : false;
            t.text += char(c);
        }
    }
}


void tokeniser::readVariable(token& t)
{
    t.type = token::kind::variable;
    get();   // $
    if (look() == '{')
    {
        int depth = 0;
        while (true)
        {
            const int c = get();
            if (c < 0)
            {
                error(t.line, "Unterminated variable '$"
                    + dictionaryDetail::clip(t.text)
                    + "': expected '}', found end of file");
            }
            t.text += char(c);
            if (c == '{')
            {
                ++depth;
            }
            else if (c == '}' && --depth == 0)
            {
                break;
            }
        }
        if (t.text == "{}")
        {
            error(t.line, "Empty variable name '${}'");
        }
        return;
    }

    int depth = 0;
    while (isVariableChar(look()))
    {
        const int c = look();
        if (c == '(')
        {
            ++depth;
        }
        else if (c == ')')
        {
            if (depth == 0)
            {
                break;
            }
            --depth;
        }
        t.text += char(get());
    }
    if (t.text.empty())
    {
        error(t.line, "Bad variable: expected a name after '$', found "
            + (look() < 0 ? std::string("end of file")
                          : "'" + std::string(1, char(look())) + "'"));
    }
    if (depth > 0)
    {
        error(t.line, "Unbalanced parentheses in variable '$"
            + dictionaryDetail::clip(t.text)
            + "': expected ')'");
    }
}


void tokeniser::readHash(token& t)
{
    get();   // #
    if (look() == '{')
    {
        t.type = token::kind::verbatim;
        get();
        while (true)
        {
            const int c = get();
            if (c < 0)
            {
                error(t.line, "Unterminated verbatim string #{ (opened at "
                    "line " + std::to_string(t.line)
                    + "): expected '#}', found end of file");
            }
            if (c == '#' && look() == '}')
            {
                get();
                return;
            }
            t.text += char(c);
        }
    }

    t.type = token::kind::directive;
    while (look() >= 0
        && (std::isalnum(look()) || look() == '_'))
    {
        t.text += char(get());
    }
    if (t.text.empty())
    {
        error(t.line, "Bad directive: expected a name after '#', found "
            + (look() < 0 ? std::string("end of file")
                          : "'" + std::string(1, char(look())) + "'"));
    }
}


std::vector<token> tokeniser::tokenise(const std::string& text,
                                       const std::string& file)
{
    tokeniser tk(text, file);
    std::vector<token> tokens;
    token t;
    while (tk.read(t))
    {
        tokens.push_back(t);
    }
    return tokens;
}


bool isValidWord(const std::string& text)
{
    if (text.empty())
    {
        return false;
    }
    for (const char c : text)
    {
        if (!isWordChar(static_cast<unsigned char>(c)))
        {
            return false;
        }
    }
    const int c = static_cast<unsigned char>(text[0]);
    if (isDigit(c) || c == '.' || c == '-' || c == '#' || c == '\''
     || isPunctuationChar(c))
    {
        return false;
    }
    try
    {
        const auto tokens = tokeniser::tokenise(text, "<word>");
        return tokens.size() == 1 && tokens[0].type == token::kind::word
            && tokens[0].text == text;
    }
    catch (const FatalError&)
    {
        return false;
    }
}

} // End namespace sphvcpm
