save () {
    # Quote each argument for the eval below, as the template's sed did (' becomes '\'',
    # the whole wrapped in '...' and a line continuation), in the shell itself: the template
    # forked one sed per argument (12-15 s for 5000 arguments).
    for i do
        quoted=
        while :; do
            case $i in
                *\'*) quoted="$quoted${i%%\'*}'\\''"; i=${i#*\'} ;;
                *) break ;;
            esac
        done
        printf "'%s%s' \\\\\n" "$quoted" "$i"
    done
    echo " "
}
