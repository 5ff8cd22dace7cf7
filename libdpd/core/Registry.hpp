#pragma once
// Types chosen by name at run time (as OpenFOAM's run-time selection): a family of types keeps one
// Registry, each type adds its maker under its name on one line of the family's registration file,
// and a case names the type. The maker reads the type's own coefficients.
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dpd {

template <class Base, class... Args>
class Registry {
public:
    using Maker = std::function<std::unique_ptr<Base>(Args...)>;

    // Throws std::logic_error for a name added twice.
    Registry& add(const std::string& name, Maker maker) {
        if (find(name)) throw std::logic_error("type '" + name + "' registered twice");
        entries_.push_back({name, std::move(maker)});
        return *this;
    }
    bool has(const std::string& name) const { return find(name) != nullptr; }
    // Throws std::invalid_argument naming the valid types for an unknown name.
    std::unique_ptr<Base> make(const std::string& name, Args... args) const {
        const Entry* e = find(name);
        if (!e) throw std::invalid_argument("unknown type '" + name + "' (expected " + nameList() + ")");
        return e->maker(std::forward<Args>(args)...);
    }
    // In the order they were added.
    std::vector<std::string> names() const {
        std::vector<std::string> n;
        for (const Entry& e : entries_) n.push_back(e.name);
        return n;
    }
    // "A, B or C".
    std::string nameList() const {
        std::string list;
        for (std::size_t k = 0; k < entries_.size(); ++k)
            list += (k == 0 ? "" : (k + 1 == entries_.size() ? " or " : ", ")) + entries_[k].name;
        return list;
    }

private:
    struct Entry {
        std::string name;
        Maker maker;
    };
    const Entry* find(const std::string& name) const {
        for (const Entry& e : entries_)
            if (e.name == name) return &e;
        return nullptr;
    }
    std::vector<Entry> entries_;
};

}  // namespace dpd
