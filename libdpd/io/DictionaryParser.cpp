#include "io/DictionaryParser.hpp"

#include "core/Error.hpp"
#include "io/DictionaryDetail.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <system_error>

namespace dpd {

using detail::DictEntry;
using detail::joinPath;
using detail::kMaxIncludeDepth;
using detail::kMaxNesting;
using detail::readText;

// The dictionaries being read are kept in scopes_, innermost last, for macros to search.
class DictionaryParser {
public:
    explicit DictionaryParser(Dictionary& root) { scopes_.push_back(&root); }

    // Reads one file's text into dict. Included files are read with dropHeader: their FoamFile
    // header describes that file, not the dictionary it is included into.
    void parseFile(const std::string& text, const std::string& file, Dictionary& dict, bool dropHeader) {
        Cursor c{tokenizeDictionary(text, file), 0, file};
        parseBody(c, dict, nullptr, "", dropHeader);
    }

private:
    struct Cursor {
        std::vector<DictToken> tokens;  // never empty: ends with an End token
        std::size_t pos = 0;
        std::string file;
        const DictToken& peek(std::size_t ahead = 0) const {
            return tokens[std::min(pos + ahead, tokens.size() - 1)];
        }
        const DictToken& next() {
            const DictToken& t = peek();
            if (pos + 1 < tokens.size()) ++pos;
            return t;
        }
    };

    // Entries up to the '}' matching openBrace, or up to the end of the file when openBrace is null.
    void parseBody(Cursor& c, Dictionary& dict, const DictToken* openBrace, const std::string& name,
                   bool dropHeader) {
        for (;;) {
            const DictToken& t = c.next();
            if (t.kind == DictToken::Kind::End) {
                if (openBrace)
                    throw InputError(c.file, openBrace->line, name,
                                     "unclosed '{': no matching '}' before the end of the file");
                return;
            }
            if (t.isPunct('}')) {
                if (openBrace) return;
                throw InputError(c.file, t.line, "", "unexpected '}' with no matching '{'");
            }
            if (t.isPunct(';')) continue;  // "};" after a sub-dictionary is common OpenFOAM style
            if (t.isPunct(')')) throw InputError(c.file, t.line, "", "unexpected ')' with no matching '('");
            if (t.kind == DictToken::Kind::Punct)
                throw InputError(c.file, t.line, "", "expected a keyword but found '" + t.text + "'");
            if (t.kind == DictToken::Kind::Directive) parseDirective(c, dict, t);
            else if (t.kind == DictToken::Kind::Macro) parseMacroEntry(c, dict, t);
            else parseEntry(c, dict, t, dropHeader);
        }
    }

    void parseEntry(Cursor& c, Dictionary& dict, const DictToken& keyTok, bool dropHeader) {
        if (c.peek().isPunct('{')) return parseSubDict(c, dict, keyTok, dropHeader);
        if (c.peek().kind == DictToken::Kind::Macro && c.peek(1).isPunct(';')) {
            const DictEntry& target = resolveMacro(c, c.peek(), keyTok.text);
            if (target.dict) return copySubDict(c, dict, keyTok, *target.dict);
        }
        DictEntry entry(keyTok.text, c.file, keyTok.line);
        entry.value = readValue(c, keyTok);
        noteRepeated(dict, entry);
        dict.insert(std::move(entry));
    }

    // A keyword given twice in one dictionary of one file is most likely a slip: the log says so.
    void noteRepeated(const Dictionary& dict, const DictEntry& entry) {
        const DictEntry* old = dict.findEntry(entry.key);
        if (!old || old->file != entry.file) return;
        const std::string where = dict.path_.empty() ? "" : " in " + dict.path_;
        scopes_.front()->warnings_.push_back(
            entry.file + ":" + std::to_string(entry.line) + ": keyword '" + entry.key + "' given twice" + where +
            " (lines " + std::to_string(old->line) + " and " + std::to_string(entry.line) + "): " +
            (old->dict && entry.dict ? "the two are merged" : "the last one is used"));
    }

    void parseSubDict(Cursor& c, Dictionary& dict, const DictToken& keyTok, bool dropHeader) {
        const DictToken& brace = c.next();
        if (scopes_.size() > static_cast<std::size_t>(kMaxNesting))
            throw InputError(c.file, keyTok.line, keyTok.text,
                             "sub-dictionaries nested more than " + std::to_string(kMaxNesting) + " levels deep");
        auto child = std::make_unique<Dictionary>(c.file);
        child->line_ = keyTok.line;
        child->path_ = joinPath(dict.path_, keyTok.text);
        scopes_.push_back(child.get());
        parseBody(c, *child, &brace, keyTok.text, false);
        scopes_.pop_back();
        if (dropHeader && keyTok.text == "FoamFile") return;
        DictEntry entry(keyTok.text, c.file, keyTok.line);
        entry.dict = std::move(child);
        noteRepeated(dict, entry);
        dict.insert(std::move(entry));
    }

    // "key $otherDict;" makes key a copy of that sub-dictionary.
    void copySubDict(Cursor& c, Dictionary& dict, const DictToken& keyTok, const Dictionary& source) {
        c.next();  // the macro
        c.next();  // ';'
        DictEntry entry(keyTok.text, c.file, keyTok.line);
        entry.dict = std::make_unique<Dictionary>(source);
        entry.dict->file_ = c.file;
        entry.dict->line_ = keyTok.line;
        entry.dict->rescope(joinPath(dict.path_, keyTok.text));
        noteRepeated(dict, entry);
        dict.insert(std::move(entry));
    }

    // The tokens of a value up to its ';'. A missing ';' is caught when the value runs into '}', '{'
    // or the end of the file, or when a new line starts outside parentheses: values span lines only
    // inside lists, so "deltaT 0.01 <newline> endTime 10;" is a forgotten ';' after 0.01.
    std::vector<DictToken> readValue(Cursor& c, const DictToken& keyTok) {
        const std::string& key = keyTok.text;
        std::vector<DictToken> value;
        std::vector<int> openParens;  // lines of the '(' not closed yet
        int lastLine = keyTok.line;
        for (;;) {
            const DictToken& t = c.peek();
            if (endsValue(t)) {
                if (!openParens.empty())
                    throw InputError(c.file, openParens.back(), key,
                                     "unclosed '(': no matching ')' before " + describeEnd(t));
                if (t.isPunct(';')) {
                    c.next();
                    return value;
                }
                throw InputError(c.file, lastLine, key, "missing ';' at the end of the entry");
            }
            c.next();
            if (t.isPunct('(')) {
                openParens.push_back(t.line);
                if (openParens.size() > static_cast<std::size_t>(kMaxNesting))
                    throw InputError(c.file, t.line, key, "lists nested more than " + std::to_string(kMaxNesting) +
                                                              " levels deep");
            } else if (t.isPunct(')')) {
                if (openParens.empty())
                    throw InputError(c.file, t.line, key, "unexpected ')' with no matching '('");
                openParens.pop_back();
            } else if (t.kind == DictToken::Kind::Directive) {
                throw InputError(c.file, t.line, key, t.text + " cannot appear inside a value");
            } else if (openParens.empty() && !value.empty() && t.line > lastLine) {
                throw InputError(c.file, lastLine, key,
                                 "missing ';' at the end of the entry (a value continues onto the next "
                                 "line only inside parentheses)");
            }
            if (t.kind == DictToken::Kind::Macro) expandMacro(c, t, key, value);
            else value.push_back(t);
            lastLine = t.line;
        }
    }

    static bool endsValue(const DictToken& t) {
        return t.kind == DictToken::Kind::End || t.isPunct(';') || t.isPunct('{') || t.isPunct('}');
    }
    static std::string describeEnd(const DictToken& t) {
        return t.kind == DictToken::Kind::End ? "the end of the file" : "'" + t.text + "'";
    }

    void expandMacro(const Cursor& c, const DictToken& macro, const std::string& key,
                     std::vector<DictToken>& value) {
        const DictEntry& target = resolveMacro(c, macro, key);
        if (target.dict)
            throw InputError(c.file, macro.line, key,
                             "$" + macro.text + " names a sub-dictionary; use it alone, as in 'key $" +
                                 macro.text + ";'");
        for (DictToken t : target.value) {
            t.line = macro.line;  // errors about the value point at the use of the macro
            value.push_back(std::move(t));
        }
    }

    // "$defaults;" inside a dictionary merges the entries of the sub-dictionary defaults into it.
    void parseMacroEntry(Cursor& c, Dictionary& dict, const DictToken& macro) {
        const std::string keyword = "$" + macro.text;
        const DictEntry& target = resolveMacro(c, macro, keyword);
        if (!target.dict)
            throw InputError(c.file, macro.line, keyword,
                             "a macro standing as an entry must name a sub-dictionary");
        if (!c.peek().isPunct(';')) throw InputError(c.file, macro.line, keyword, "missing ';' after the macro");
        c.next();
        const Dictionary source = *target.dict;  // a copy: merging may move the entry it lives in
        dict.mergeFrom(source);
    }

    // $name: the innermost scope that has it wins; $a.b.c walks into sub-dictionaries; $:a.b starts
    // at the top level.
    const DictEntry& resolveMacro(const Cursor& c, const DictToken& macro, const std::string& key) const {
        const std::string& name = macro.text;
        const DictEntry* found = nullptr;
        if (name[0] == ':') {
            found = lookup(*scopes_.front(), name.substr(1));
        } else {
            for (auto scope = scopes_.rbegin(); scope != scopes_.rend() && !found; ++scope)
                found = lookup(**scope, name);
        }
        if (!found)
            throw InputError(c.file, macro.line, key,
                             "unknown macro $" + name + ": no such keyword in this or an enclosing dictionary");
        return *found;
    }

    // A keyword may itself contain dots, so the whole name is tried before each split at a dot.
    static const DictEntry* lookup(const Dictionary& dict, const std::string& name) {
        if (const DictEntry* e = dict.findEntry(name)) return e;
        for (std::size_t dot = name.find('.'); dot != std::string::npos; dot = name.find('.', dot + 1)) {
            const DictEntry* head = dict.findEntry(name.substr(0, dot));
            if (!head || !head->dict) continue;
            if (const DictEntry* e = lookup(*head->dict, name.substr(dot + 1))) return e;
        }
        return nullptr;
    }

    void parseDirective(Cursor& c, Dictionary& dict, const DictToken& directive) {
        const bool optional = directive.text == "#includeIfPresent";
        if (directive.text != "#include" && !optional)
            throw InputError(c.file, directive.line, directive.text,
                             "unknown directive (supported: #include, #includeIfPresent)");
        const DictToken& name = c.next();
        if (name.kind != DictToken::Kind::String && name.kind != DictToken::Kind::Word)
            throw InputError(c.file, directive.line, directive.text, "expected a file name, e.g. #include \"file\"");
        includeFile(c, dict, directive, name.text, optional);
    }

    void includeFile(const Cursor& c, Dictionary& dict, const DictToken& directive, const std::string& name,
                     bool optional) {
        namespace fs = std::filesystem;
        fs::path path(name);
        if (path.is_relative()) path = fs::path(c.file).parent_path() / path;
        std::string text;
        if (!readText(path.string(), text)) {
            if (optional) return;
            throw InputError(c.file, directive.line, directive.text,
                             "cannot open included file '" + name + "' (looked for " + path.string() + ")");
        }
        if (includeDepth_ >= kMaxIncludeDepth)
            throw InputError(c.file, directive.line, directive.text,
                             "includes nested more than " + std::to_string(kMaxIncludeDepth) +
                                 " deep (does a file include itself?)");
        ++includeDepth_;
        parseFile(text, path.string(), dict, true);
        --includeDepth_;
    }

    std::vector<Dictionary*> scopes_;  // the dictionaries being read, innermost last
    int includeDepth_ = 0;
};

void parseDictionaryText(const std::string& text, const std::string& file, Dictionary& root) {
    DictionaryParser(root).parseFile(text, file, root, false);
}

}  // namespace dpd
