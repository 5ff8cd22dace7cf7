#include "io/DictionaryLexer.hpp"

#include "core/Error.hpp"

namespace dpd {

namespace {

bool isPunctChar(char c) { return c == '{' || c == '}' || c == '(' || c == ')' || c == ';'; }

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

class Lexer {
public:
    Lexer(const std::string& text, const std::string& file) : text_(text), file_(file) {}

    std::vector<DictToken> run() {
        std::vector<DictToken> tokens;
        for (;;) {
            skipSpaceAndComments();
            if (atEnd()) break;
            tokens.push_back(readToken());
        }
        tokens.push_back({DictToken::Kind::End, "", line_});
        return tokens;
    }

private:
    bool atEnd() const { return pos_ >= text_.size(); }
    char peek(std::size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }
    // Comments may start right after a word ("1.0// note"), so words stop at "//" and "/*" as well.
    bool atCommentStart() const { return peek() == '/' && (peek(1) == '/' || peek(1) == '*'); }

    void advance() {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
    }

    void skipSpaceAndComments() {
        while (!atEnd()) {
            if (isSpace(peek())) {
                advance();
            } else if (peek() == '/' && peek(1) == '/') {
                while (!atEnd() && peek() != '\n') advance();
            } else if (peek() == '/' && peek(1) == '*') {
                skipBlockComment();
            } else {
                return;
            }
        }
    }

    void skipBlockComment() {
        const int startLine = line_;
        pos_ += 2;
        while (!atEnd() && !(peek() == '*' && peek(1) == '/')) advance();
        if (atEnd())
            throw InputError(file_, startLine, "", "unterminated comment: '/*' has no closing '*/'");
        pos_ += 2;
    }

    DictToken readToken() {
        const char c = peek();
        if (isPunctChar(c)) {
            advance();
            return {DictToken::Kind::Punct, std::string(1, c), line_};
        }
        if (c == '"') return readString();
        if (c == '#') return readPrefixed(DictToken::Kind::Directive);
        if (c == '$') return readMacro();
        return {DictToken::Kind::Word, readWordChars(), line_};
    }

    std::string readWordChars() {
        std::string word;
        while (!atEnd() && !isSpace(peek()) && !isPunctChar(peek()) && peek() != '"' && !atCommentStart()) {
            word += peek();
            advance();
        }
        return word;
    }

    // A string must close on its own line: a forgotten quote is then reported where it happened
    // instead of swallowing the rest of the file.
    DictToken readString() {
        const int startLine = line_;
        advance();  // opening quote
        std::string s;
        while (!atEnd() && peek() != '"' && peek() != '\n') {
            if (peek() == '\\' && (peek(1) == '"' || peek(1) == '\\')) advance();
            s += peek();
            advance();
        }
        if (atEnd() || peek() == '\n')
            throw InputError(file_, startLine, "", "unterminated string: missing closing '\"'");
        advance();  // closing quote
        return {DictToken::Kind::String, s, startLine};
    }

    DictToken readPrefixed(DictToken::Kind kind) {
        const int startLine = line_;
        advance();  // '#'
        const std::string name = readWordChars();
        if (name.empty()) throw InputError(file_, startLine, "", "'#' must be followed by a directive name");
        return {kind, "#" + name, startLine};
    }

    DictToken readMacro() {
        const int startLine = line_;
        advance();  // '$'
        std::string name;
        if (peek() == '{') {  // ${name}: lets a macro sit directly before other characters
            advance();
            while (!atEnd() && peek() != '}' && peek() != '\n') {
                name += peek();
                advance();
            }
            if (peek() != '}') throw InputError(file_, startLine, "", "unterminated macro: '${' has no closing '}'");
            advance();
        } else {
            name = readWordChars();
        }
        if (name.empty()) throw InputError(file_, startLine, "", "'$' must be followed by a keyword name");
        return {DictToken::Kind::Macro, name, startLine};
    }

    const std::string& text_;
    const std::string& file_;
    std::size_t pos_ = 0;
    int line_ = 1;
};

}  // namespace

std::vector<DictToken> tokenizeDictionary(const std::string& text, const std::string& fileName) {
    return Lexer(text, fileName).run();
}

bool isPlainWord(const std::string& s) {
    if (s.empty() || s[0] == '#' || s[0] == '$') return false;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (isSpace(c) || isPunctChar(c) || c == '"') return false;
        if (c == '/' && i + 1 < s.size() && (s[i + 1] == '/' || s[i + 1] == '*')) return false;
    }
    return true;
}

std::string quoteString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string tokenText(const DictToken& t) {
    switch (t.kind) {
        case DictToken::Kind::String: return quoteString(t.text);
        case DictToken::Kind::Macro: return "$" + t.text;
        default: return t.text;
    }
}

}  // namespace dpd
