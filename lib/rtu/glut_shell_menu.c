/* SPDX-License-Identifier: Apache-2.0 */
/*
 * glut_shell_menu.c - rtuCreateMenu, rtuAddMenuEntry, rtuAddSubMenu,
 * rtuAttachMenu ... (GLUT 3, Kilgard 1996, sec. 6).  A ray traced window
 * has no pop-up menus: in a window, pressing the button a menu is attached
 * to opens it in the terminal (its entries printed with the keys that
 * choose them: 1-9, then a-z); the next key chooses, Escape closes.
 * Headless, TRACELIST_EVENTS chooses an entry by its label ("m:Label").
 * Either way the menu's callback is called with the entry's value and
 * with that menu current, as GLUT does.
 */
#include "glut_shell.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Keys of the entries of an open menu, in order. */
static const char menu_keys[] = "123456789abcdefghijklmnopqrstuvwxyz";

static struct rtu_menu *current(struct rtu_shell *s, const char *caller)
{
    if (s->current_menu < 1 || s->current_menu > RTU_SHELL_MAX_MENUS ||
        !s->menus[s->current_menu].live) {
        rtu_shell_warn(caller, "no current menu");
        return NULL;
    }
    return &s->menus[s->current_menu];
}

int rtuCreateMenu(void (*func)(int value))
{
    struct rtu_shell *s = rtu_shell_state();
    int id;
    for (id = 1; id <= RTU_SHELL_MAX_MENUS; id++)
        if (!s->menus[id].live)
            break;
    if (id > RTU_SHELL_MAX_MENUS || !func) {
        rtu_shell_warn("rtuCreateMenu", func ? "too many menus (64)" : "NULL callback");
        return 0;
    }
    memset(&s->menus[id], 0, sizeof(s->menus[id]));
    s->menus[id].live = 1;
    s->menus[id].func = func;
    s->current_menu = id;
    return id;
}

static void free_menu(struct rtu_menu *m)
{
    int i;
    for (i = 0; i < m->count; i++)
        free(m->entries[i].label);
    free(m->entries);
    memset(m, 0, sizeof(*m));
}

void rtuDestroyMenu(int menu)
{
    struct rtu_shell *s = rtu_shell_state();
    int b;
    if (menu < 1 || menu > RTU_SHELL_MAX_MENUS || !s->menus[menu].live) {
        rtu_shell_warn("rtuDestroyMenu", "no such menu");
        return;
    }
    free_menu(&s->menus[menu]);
    for (b = 0; b < RTU_SHELL_BUTTONS; b++)
        if (s->attached[b] == menu)
            s->attached[b] = 0;
    if (s->current_menu == menu)
        s->current_menu = 0;
}

int rtuGetMenu(void)
{
    return rtu_shell_state()->current_menu;
}

void rtuSetMenu(int menu)
{
    struct rtu_shell *s = rtu_shell_state();
    if (menu < 1 || menu > RTU_SHELL_MAX_MENUS || !s->menus[menu].live) {
        rtu_shell_warn("rtuSetMenu", "no such menu");
        return;
    }
    s->current_menu = menu;
}

static void add_entry(const char *caller, const char *label, int value, int submenu)
{
    struct rtu_shell *s = rtu_shell_state();
    struct rtu_menu *m = current(s, caller);
    char *copy;
    if (!m)
        return;
    if (!label)
        label = "";
    if (m->count == m->capacity) {
        int cap = m->capacity ? 2 * m->capacity : 8;
        struct rtu_menu_entry *grown = realloc(m->entries, (size_t)cap * sizeof(*grown));
        if (!grown) {
            rtu_shell_warn(caller, "out of memory");
            return;
        }
        m->entries = grown;
        m->capacity = cap;
    }
    copy = malloc(strlen(label) + 1);
    if (!copy) {
        rtu_shell_warn(caller, "out of memory");
        return;
    }
    strcpy(copy, label);
    m->entries[m->count].label = copy;
    m->entries[m->count].value = value;
    m->entries[m->count].submenu = submenu;
    m->count++;
}

void rtuAddMenuEntry(const char *label, int value)
{
    add_entry("rtuAddMenuEntry", label, value, 0);
}

void rtuAddSubMenu(const char *label, int submenu)
{
    struct rtu_shell *s = rtu_shell_state();
    if (submenu < 1 || submenu > RTU_SHELL_MAX_MENUS || !s->menus[submenu].live) {
        rtu_shell_warn("rtuAddSubMenu", "no such submenu");
        return;
    }
    add_entry("rtuAddSubMenu", label, 0, submenu);
}

void rtuAttachMenu(int button)
{
    struct rtu_shell *s = rtu_shell_state();
    if (button < 0 || button >= RTU_SHELL_BUTTONS || !current(s, "rtuAttachMenu"))
        return;
    s->attached[button] = s->current_menu;
}

void rtuDetachMenu(int button)
{
    struct rtu_shell *s = rtu_shell_state();
    if (button >= 0 && button < RTU_SHELL_BUTTONS)
        s->attached[button] = 0;
}

/* Calls menu `id`'s callback with `value`, that menu current meanwhile. */
static void choose(struct rtu_shell *s, int id, int value)
{
    const int saved = s->current_menu;
    s->current_menu = id;
    s->menus[id].func(value);
    if (saved >= 1 && saved <= RTU_SHELL_MAX_MENUS && s->menus[saved].live)
        s->current_menu = saved;
}

/* Label equality, a '_' in `wanted` standing for a space (or itself, so
 * that a label with an underscore can be chosen too). */
static int label_matches(const char *label, const char *wanted)
{
    for (; *label && *wanted; label++, wanted++)
        if (*label != *wanted && !(*wanted == '_' && *label == ' '))
            return 0;
    return *label == '\0' && *wanted == '\0';
}

/* Searches menu `id` and its submenus (depth-limited against cycles). */
static int select_in(struct rtu_shell *s, int id, const char *label, int depth)
{
    struct rtu_menu *m = &s->menus[id];
    int i;
    if (depth > RTU_SHELL_MAX_MENUS || !m->live)
        return 0;
    for (i = 0; i < m->count; i++)
        if (!m->entries[i].submenu && label_matches(m->entries[i].label, label)) {
            choose(s, id, m->entries[i].value);
            return 1;
        }
    for (i = 0; i < m->count; i++)
        if (m->entries[i].submenu && select_in(s, m->entries[i].submenu, label, depth + 1))
            return 1;
    return 0;
}

int rtu_menu_select_label(struct rtu_shell *s, const char *label)
{
    int b, id, any = 0;
    for (b = 0; b < RTU_SHELL_BUTTONS; b++)
        if (s->attached[b]) {
            any = 1;
            if (select_in(s, s->attached[b], label, 0))
                return 1;
        }
    if (any)
        return 0;
    for (id = 1; id <= RTU_SHELL_MAX_MENUS; id++)
        if (s->menus[id].live && select_in(s, id, label, 0))
            return 1;
    return 0;
}

void rtu_menu_open(struct rtu_shell *s, int menu)
{
    const struct rtu_menu *m = &s->menus[menu];
    int i;
    if (!m->live)
        return;
    s->open_menu = menu;
    printf("menu (press a key, Escape closes):\n");
    for (i = 0; i < m->count && i < (int)sizeof(menu_keys) - 1; i++)
        printf("  %c  %s%s\n", menu_keys[i], m->entries[i].label,
               m->entries[i].submenu ? " >" : "");
    fflush(stdout);
}

int rtu_menu_key(struct rtu_shell *s, int key)
{
    const struct rtu_menu *m;
    const char *at;
    int i;
    if (!s->open_menu)
        return 0;
    m = &s->menus[s->open_menu];
    if (key == 27 || !m->live) {
        s->open_menu = 0;
        printf("menu closed\n");
        fflush(stdout);
        return 1;
    }
    at = key > 0 && key < 256 ? strchr(menu_keys, key) : NULL;
    i = at ? (int)(at - menu_keys) : -1;
    if (i < 0 || i >= m->count)
        return 1; /* not an entry: the menu stays open */
    if (m->entries[i].submenu) {
        rtu_menu_open(s, m->entries[i].submenu);
        return 1;
    }
    {
        const int id = s->open_menu;
        s->open_menu = 0;
        choose(s, id, m->entries[i].value);
    }
    return 1;
}

void rtu_menu_free_all(struct rtu_shell *s)
{
    int id;
    for (id = 1; id <= RTU_SHELL_MAX_MENUS; id++)
        if (s->menus[id].live)
            free_menu(&s->menus[id]);
    memset(s->attached, 0, sizeof(s->attached));
    s->current_menu = 0;
    s->open_menu = 0;
}
