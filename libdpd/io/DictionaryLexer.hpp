#pragma once
// Tokens of the OpenFOAM dictionary syntax. The lexer only splits text into words, quoted strings,
// punctuation, #directives and $macros and drops comments; what the tokens mean is the parser's job
// (Dictionary.cpp). Numbers are plain words: only the typed getters decide whether "1e-3" is a number,
// so a value keeps exactly the text the user wrote and writes back unchanged.
#include <string>
#include <vector>

namespace dpd {

struct DictToken {
    enum class Kind {
        Word,       // keyword, number, switch, bare word such as fluid-wall
        String,     // "quoted text" (text holds it without quotes, escapes resolved)
        Punct,      // one of { } ( ) ;
        Directive,  // #include, #includeIfPresent, ... (text holds the '#')
        Macro,      // $name or ${name} (text holds the name without '$' and braces)
        End         // end of input; line is the last line of the file
    };
    Kind kind = Kind::End;
    std::string text;
    int line = 0;

    bool isPunct(char c) const { return kind == Kind::Punct && text.size() == 1 && text[0] == c; }
};

// Splits text into tokens, always ending with one End token. Throws InputError naming fileName and
// the line where an unterminated string or comment began.
std::vector<DictToken> tokenizeDictionary(const std::string& text, const std::string& fileName);

// True when s can be written back as a bare word (no quotes needed) and reads back as one Word token.
bool isPlainWord(const std::string& s);

// s in double quotes, with '"' and '\' escaped so that the lexer reads back exactly s.
std::string quoteString(const std::string& s);

// How a token is written back into a dictionary file.
std::string tokenText(const DictToken& t);

}  // namespace dpd
