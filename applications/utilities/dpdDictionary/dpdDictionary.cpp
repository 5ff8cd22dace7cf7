// dpdDictionary: print or set one entry of a dictionary file, e.g.
//   dpdDictionary system/controlDict -entry endTime -set 20
//   dpdDictionary constant/dpdProperties -entry pairCoeffs/fluid-wall/gamma -value
#include "app/ToolCommandLine.hpp"
#include "io/DictionaryEdit.hpp"

#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) {
    return dpd::runTool("dpdDictionary", [&] {
        dpd::ToolCommandLine cl("dpdDictionary", "print or set an entry of a dictionary (like foamDictionary)", false);
        std::string file, entry, value;
        cl.addOptions()("file", boost::program_options::value<std::string>(&file), "the dictionary file")(
            "entry", boost::program_options::value<std::string>(&entry), "slash-separated entry path, e.g. walls/lower/velocity")(
            "set", boost::program_options::value<std::string>(&value), "new value, in dictionary syntax")(
            "value", "print the entry's value");
        cl.setPositional("file");
        if (!cl.parse(argc, argv)) return;
        if (file.empty() || entry.empty()) throw std::invalid_argument("usage: dpdDictionary FILE -entry PATH [-set VALUE | -value]");
        if (cl.has("set")) dpd::setDictionaryEntry(file, entry, value);
        else std::cout << dpd::readDictionaryEntry(file, entry) << "\n";
    });
}
